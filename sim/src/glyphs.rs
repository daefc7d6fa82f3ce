//! A 5 × 7 bitmap font for the few labels drawn into pictures (a heat map's colour bar: its ends and its unit), so
//! a PNG carries its own scale on a machine without any font installed.

/// The rows of a glyph, top first, each 5 bits (the leftmost column the highest bit); `None` for a character the
/// font does not draw.
fn rows(c: char) -> Option<[u8; 7]> {
    Some(match c {
        '0' => [0b01110, 0b10001, 0b10011, 0b10101, 0b11001, 0b10001, 0b01110],
        '1' => [0b00100, 0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110],
        '2' => [0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b01000, 0b11111],
        '3' => [0b11110, 0b00001, 0b00001, 0b01110, 0b00001, 0b00001, 0b11110],
        '4' => [0b00010, 0b00110, 0b01010, 0b10010, 0b11111, 0b00010, 0b00010],
        '5' => [0b11111, 0b10000, 0b11110, 0b00001, 0b00001, 0b10001, 0b01110],
        '6' => [0b00110, 0b01000, 0b10000, 0b11110, 0b10001, 0b10001, 0b01110],
        '7' => [0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b01000, 0b01000],
        '8' => [0b01110, 0b10001, 0b10001, 0b01110, 0b10001, 0b10001, 0b01110],
        '9' => [0b01110, 0b10001, 0b10001, 0b01111, 0b00001, 0b00010, 0b01100],
        '.' => [0, 0, 0, 0, 0, 0b01100, 0b01100],
        '-' => [0, 0, 0, 0b11111, 0, 0, 0],
        ' ' => [0; 7],
        'L' => [0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b11111],
        'S' => [0b01111, 0b10000, 0b10000, 0b01110, 0b00001, 0b00001, 0b11110],
        'B' => [0b11110, 0b10001, 0b10001, 0b11110, 0b10001, 0b10001, 0b11110],
        'd' => [0b00001, 0b00001, 0b01101, 0b10011, 0b10001, 0b10011, 0b01101],
        'e' => [0, 0, 0b01110, 0b10001, 0b11111, 0b10000, 0b01110],
        'g' => [0, 0b01111, 0b10001, 0b10011, 0b01101, 0b00001, 0b01110],
        '°' => [0b01100, 0b10010, 0b10010, 0b01100, 0, 0, 0],
        _ => return None,
    })
}

/// Width in pixels of `text` drawn at `scale` (each glyph 5 columns and a column of space, times the scale).
pub fn width(text: &str, scale: usize) -> usize {
    text.chars().count() * 6 * scale
}

/// Draw `text` with its top-left corner at (x, y), `scale` pixels a font dot, through `dot(x, y)` for each lit
/// pixel. A character the font does not draw is an error: a label must be read as written.
pub fn draw(text: &str, x: usize, y: usize, scale: usize, dot: &mut dyn FnMut(usize, usize)) -> Result<(), String> {
    for (i, c) in text.chars().enumerate() {
        let g = rows(c).ok_or_else(|| format!("the picture font has no glyph for {c:?} (in {text:?})"))?;
        for (r, bits) in g.iter().enumerate() {
            for col in 0..5 {
                if bits >> (4 - col) & 1 == 1 {
                    for dy in 0..scale {
                        for dx in 0..scale {
                            dot(x + (i * 6 + col) * scale + dx, y + r * scale + dy);
                        }
                    }
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every glyph differs from every other (a typo in a row table would make two characters read alike), and each
    /// one but the space lights at least one dot.
    #[test]
    fn the_glyphs_are_distinct_and_drawn() {
        let all = "0123456789.- LSBdeg°";
        for (i, a) in all.chars().enumerate() {
            for b in all.chars().skip(i + 1) {
                assert_ne!(rows(a), rows(b), "{a:?} and {b:?}");
            }
            let mut n = 0;
            draw(&a.to_string(), 0, 0, 2, &mut |_, _| n += 1).unwrap();
            assert_eq!(n == 0, a == ' ', "{a:?}: {n} dots");
            // at scale 2 each dot is 4 pixels
            assert_eq!(n % 4, 0);
        }
        // eight 5 × 7 glyphs, each with a column of space after it, at scale 2; and every dot drawn lies inside
        // that width and the 7 rows (14 at scale 2)
        assert_eq!(width("3.00 LSB", 2), 8 * (5 + 1) * 2);
        let (mut right, mut bottom) = (0, 0);
        draw("3.00 LSB", 0, 0, 2, &mut |x, y| (right, bottom) = (right.max(x), bottom.max(y))).unwrap();
        assert!(right < width("3.00 LSB", 2) && bottom < 14, "a dot at ({right}, {bottom})");
        assert!(draw("x", 0, 0, 1, &mut |_, _| {}).unwrap_err().contains("'x'"));
    }
}
