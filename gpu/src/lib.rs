//! Runs wellspread's WGSL ([`wellspread::wgsl::SOURCE`]) on a Vulkan
//! adapter through wgpu (Mesa's lavapipe in CI) so the tests can compare
//! every value with the CPU crate.
//!
//! [`Gpu::get`] finds an adapter or, when there is none, prints one line
//! and returns `None` (the tests then skip), unless `REQUIRE_GPU=1`, which
//! turns a missing adapter into a failure.

use std::sync::mpsc;

pub mod film;
pub mod samplers;
pub mod warps;

/// A device and its queue.
#[derive(Debug)]
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    /// The adapter's name and driver, for the test log.
    pub adapter: String,
}

/// The bytes of `words`, little-endian (what WGSL's u32s are on every
/// adapter wgpu supports).
fn bytes(words: &[u32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}

impl Gpu {
    /// The first Vulkan adapter, or `None` with one line on stderr. Panics
    /// instead when the environment variable `REQUIRE_GPU` is `1`.
    pub fn get() -> Option<Gpu> {
        let required = std::env::var("REQUIRE_GPU").is_ok_and(|v| v == "1");
        match Self::open() {
            Ok(gpu) => Some(gpu),
            Err(why) if required => panic!("REQUIRE_GPU=1 but no GPU: {why}"),
            Err(why) => {
                eprintln!(
                    "skipping the GPU test: {why} (install mesa-vulkan-drivers and libvulkan1; REQUIRE_GPU=1 makes this a failure)"
                );
                None
            }
        }
    }

    fn open() -> Result<Gpu, String> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::VULKAN;
        let instance = wgpu::Instance::new(desc);
        let adapter =
            pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
                .map_err(|e| format!("no Vulkan adapter ({e})"))?;
        let info = adapter.get_info();
        let limits = adapter.limits();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("wellspread-gpu"),
            required_limits: wgpu::Limits {
                max_storage_buffer_binding_size: limits.max_storage_buffer_binding_size,
                max_buffer_size: limits.max_buffer_size,
                ..wgpu::Limits::default()
            },
            ..Default::default()
        }))
        .map_err(|e| format!("no device ({e})"))?;
        Ok(Gpu {
            device,
            queue,
            adapter: format!("{} ({}, {})", info.name, info.driver, info.driver_info),
        })
    }

    /// Compiles `shader`'s entry point `main` (workgroup size 64) with
    /// three bindings: `@binding(0)` a uniform of 16 words, `@binding(1)` a
    /// read-only storage array of u32 and `@binding(2)` a read-write one.
    pub fn kernel(&self, shader: &str) -> Kernel<'_> {
        self.kernel_with(shader, &[])
    }

    /// [`kernel`](Self::kernel) with values for the shader's `override`
    /// constants: the test shaders take the sampler's kind this way, so
    /// the driver drops the other samplers' code before compiling it.
    pub fn kernel_with(&self, shader: &str, constants: &[(&str, f64)]) -> Kernel<'_> {
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("wellspread test shader"),
                source: wgpu::ShaderSource::Wgsl(shader.into()),
            });
        let pipeline = self
            .device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: None,
                layout: None,
                module: &module,
                entry_point: Some("main"),
                compilation_options: wgpu::PipelineCompilationOptions {
                    constants,
                    ..Default::default()
                },
                cache: None,
            });
        Kernel {
            gpu: self,
            pipeline,
        }
    }

    /// [`kernel`](Self::kernel) and one [`Kernel::run`].
    pub fn run(
        &self,
        shader: &str,
        uniform: &[u32],
        input: &[u32],
        invocations: u32,
        output_words: usize,
    ) -> Vec<u32> {
        self.kernel(shader)
            .run(uniform, input, invocations, output_words)
    }
}

/// A compiled test shader (compiling is most of a run's time on lavapipe).
#[derive(Debug)]
pub struct Kernel<'a> {
    gpu: &'a Gpu,
    pipeline: wgpu::ComputePipeline,
}

impl Kernel<'_> {
    /// Runs `invocations` threads with `uniform` (zero-padded to 16 words)
    /// and `input`; returns the first `output_words` words of the output.
    pub fn run(
        &self,
        uniform: &[u32],
        input: &[u32],
        invocations: u32,
        output_words: usize,
    ) -> Vec<u32> {
        let device = &self.gpu.device;
        let queue = &self.gpu.queue;
        let pipeline = &self.pipeline;
        let storage = |size: usize, usage: wgpu::BufferUsages| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size: (size.max(4) * 4) as u64,
                usage,
                mapped_at_creation: false,
            })
        };
        let copy_dst = wgpu::BufferUsages::COPY_DST;
        let uniform_buffer = storage(16, wgpu::BufferUsages::UNIFORM | copy_dst);
        let input_buffer = storage(input.len(), wgpu::BufferUsages::STORAGE | copy_dst);
        let output_buffer = storage(
            output_words,
            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        );
        let readback = storage(
            output_words,
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        let mut params = uniform.to_vec();
        params.resize(16, 0);
        queue.write_buffer(&uniform_buffer, 0, &bytes(&params));
        if !input.is_empty() {
            queue.write_buffer(&input_buffer, 0, &bytes(input));
        }
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniform_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: input_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: output_buffer.as_entire_binding(),
                },
            ],
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            // At most 65,535 workgroups per dimension: a 2D grid of 64-wide groups.
            let groups = invocations.div_ceil(64);
            let x = groups.min(1024);
            pass.dispatch_workgroups(x, groups.div_ceil(x).max(1), 1);
        }
        encoder.copy_buffer_to_buffer(
            &output_buffer,
            0,
            &readback,
            0,
            (output_words.max(4) * 4) as u64,
        );
        queue.submit([encoder.finish()]);
        let (sender, receiver) = mpsc::channel();
        readback
            .slice(..)
            .map_async(wgpu::MapMode::Read, move |r| sender.send(r).unwrap());
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("the GPU finished");
        receiver.recv().unwrap().expect("mapped the output");
        let view = readback
            .slice(..)
            .get_mapped_range()
            .expect("read the output");
        let words = view
            .chunks_exact(4)
            .take(output_words)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect();
        drop(view);
        readback.unmap();
        words
    }
}

/// The entry point's preamble every test shader shares: the three
/// bindings of [`Gpu::run`] and the flat invocation index (64 per group,
/// 1024 groups per row of the dispatch grid).
pub const HARNESS: &str = "
@group(0) @binding(0) var<uniform> params: array<vec4<u32>, 4>;
@group(0) @binding(1) var<storage, read> input: array<u32>;
@group(0) @binding(2) var<storage, read_write> output: array<u32>;

fn invocation(id: vec3<u32>) -> u32 {
    return id.y * (1024u * 64u) + id.x;
}
";
