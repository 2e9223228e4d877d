//! Any bytes as a scene file: parsing and validation return an error or a scene, never
//! panic; a scene that validates builds a world, and that world runs a few hundred events
//! without panicking.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(scene) = exact2d::scene::Scene::from_json_str(text) else {
        return;
    };
    let Ok(built) = scene.build_world() else {
        return;
    };
    let mut world = built.into_world();
    for _ in 0..300 {
        if world.step().is_none() {
            break;
        }
    }
});
