//! The lessons' scenes, each built once for the lessons that render it.
//!
//! Lesson 08's still life (which lessons 09 and 11 render too), a mesh from a file
//! standing in it (lesson 09), and the scenes of lesson 10's path tracer (the
//! Cornell box, the furnaces, two lights), and the z-buffer's two squares (lesson 09).

pub mod meshes;
pub mod path_tracing;
pub mod placement;
pub mod squares;
pub mod still_life;

use std::path::{Path, PathBuf};

pub use meshes::{
    MESH_BYTES_PER_TRIANGLE, PlacedMesh, TEAPOT_OBJ, TORUS_OBJ, floor_and,
    floor_and_mesh, mesh_on_the_floor,
};
pub use placement::{Fit, Up};
pub use still_life::{
    STILL_LIFE_OBJECTS, still_life, still_life_cameras, still_life_pinhole,
    still_life_shadows,
};

/// `path` as given if it exists or is absolute; else, for a relative path, the same
/// path under the repository this program was built from, if the file is there. So a
/// default such as [`TORUS_OBJ`] reads as `assets/...` in `--help` and still works
/// from another folder, while a path the user gives is read where they say.
pub fn asset_path(path: impl AsRef<Path>) -> PathBuf {
    let path = path.as_ref();
    let built = Path::new(env!("CARGO_MANIFEST_DIR")).join(path);
    if path.is_relative() && !path.exists() && built.exists() {
        built
    } else {
        path.to_path_buf()
    }
}
