//! What a diagram draws, counted by colour: the lessons draw rays in blue and hit
//! points and planes in red or orange.

/// How many RGBA pixels are clearly blue (rays are drawn in blue).
pub fn blue_pixels(rgba: &[u8]) -> usize {
    rgba.chunks(4)
        .filter(|p| p[2] as i32 > p[0] as i32 + 60)
        .count()
}

/// How many RGBA pixels are clearly red or orange (hit points, planes).
pub fn red_pixels(rgba: &[u8]) -> usize {
    rgba.chunks(4)
        .filter(|p| p[0] as i32 > p[2] as i32 + 60)
        .count()
}
