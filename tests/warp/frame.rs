//! `to_world` and `to_local`: the `+z` frame about a unit normal is
//! orthonormal and right-handed, keeps the cosine with the normal, and the
//! two undo each other, for normals everywhere on the sphere (the poles
//! and the equator `z = 0`, where the frame flips, included).

use super::*;

/// Seeded unit normals, with the poles, the equator and the f32 steps
/// around `z = 0`.
fn normals() -> Vec<Vec3> {
    let mut normals = vec![
        Vec3::Z,
        -Vec3::Z,
        Vec3::X,
        -Vec3::Y,
        Vec3::new(1.0, 1.0, 0.0).normalize(),
        Vec3::new(1.0, 0.0, f32::MIN_POSITIVE),
        Vec3::new(0.0, -0.6, -f32::EPSILON).normalize(),
    ];
    normals.extend(random_points(0xf4a3e, 4096).into_iter().map(uniform_sphere));
    normals
}

#[test]
fn the_frame_is_orthonormal_and_undone_by_to_local() {
    let locals: Vec<Vec3> = random_points(0x10ca1, 64)
        .into_iter()
        .map(cosine_hemisphere)
        .collect();
    for n in normals() {
        let (t, b) = (to_world(n, Vec3::X), to_world(n, Vec3::Y));
        assert!((to_world(n, Vec3::Z) - n).length() < 1e-6, "{n}");
        assert!(
            (t.length() - 1.0).abs() < 1e-5 && (b.length() - 1.0).abs() < 1e-5,
            "{n}"
        );
        assert!(
            t.dot(b).abs() < 1e-5 && t.dot(n).abs() < 1e-5 && b.dot(n).abs() < 1e-5,
            "{n}"
        );
        assert!((t.cross(b) - n).length() < 1e-5, "{n}: not right-handed");
        for &v in &locals {
            let w = to_world(n, v);
            assert!((w.length() - 1.0).abs() < 1e-5, "{n} {v}");
            assert!((w.dot(n) - v.z).abs() < 1e-5, "{n} {v}: the cosine changed");
            assert!((to_local(n, w) - v).length() < 1e-5, "{n} {v}");
        }
    }
}
