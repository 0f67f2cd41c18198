//! Fills a 256 x 192 film with one sample per pixel from each pixel
//! sampler with a WGSL twin, on the GPU (lavapipe in CI), checks it equals
//! the CPU's film bit for bit and writes both as `out/gpu_film_<name>.ppm`
//! (red and green the film position, blue a 1D draw).
//!
//! `cargo run -p wellspread-gpu --release --example gpu_film`

use wellspread_gpu::Gpu;
use wellspread_gpu::film::{cases, cpu_film, gpu_film, ppm};

fn main() -> std::io::Result<()> {
    let (width, height) = (256, 192);
    let Some(gpu) = Gpu::get() else {
        return Ok(());
    };
    println!("adapter: {}", gpu.adapter);
    std::fs::create_dir_all("out")?;
    for case in cases(width, height) {
        let film = gpu_film(&gpu, &case, width, height);
        let same = film == cpu_film(&case, width, height);
        let path = format!("out/gpu_film_{}.ppm", case.name);
        std::fs::write(&path, ppm(&film, width, height))?;
        println!(
            "{:10} {path}: {}",
            case.name,
            if same {
                "equal to the CPU film"
            } else {
                "DIFFERS from the CPU film"
            }
        );
        assert!(same, "{}: the GPU film differs from the CPU's", case.name);
    }
    Ok(())
}
