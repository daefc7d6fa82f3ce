//! Height maps read from PNG files: grey as it is, 16-bit and colour maps with a note, other sizes resampled, bad
//! files one line naming the file.
use sim::heightmap::*;

/// Under the workspace's target folder, where the build's own files go.
fn test_dir() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-files/heightmap")
}

fn write(name: &str, img: image::DynamicImage) -> std::path::PathBuf {
    let dir = test_dir();
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    img.save_with_format(&p, image::ImageFormat::Png).unwrap();
    p
}

#[test]
fn an_8_bit_grey_power_of_two_map_is_read_as_it_is() {
    let img = image::GrayImage::from_fn(4, 4, |x, y| image::Luma([(x * 60 + y) as u8]));
    let l = load(&write("g8.png", img.into())).unwrap();
    assert_eq!(l.map.side, 4);
    assert!(l.notes.is_empty(), "{:?}", l.notes);
    assert_eq!(l.map.h[1 * 4 + 3], 181.0 / 255.0);
}

#[test]
fn a_16_bit_map_keeps_its_bits_and_a_colour_map_is_read_as_luma() {
    let img = image::ImageBuffer::<image::Luma<u16>, _>::from_fn(2, 2, |x, _| image::Luma([(x * 40_000 + 7) as u16]));
    let l = load(&write("g16.png", image::DynamicImage::ImageLuma16(img))).unwrap();
    assert_eq!(l.map.h[1], 40_007.0 / 65_535.0);
    assert!(l.notes.iter().any(|n| n.contains("16-bit")));
    let img = image::RgbImage::from_fn(2, 2, |_, _| image::Rgb([255, 0, 0]));
    let l = load(&write("rgb.png", img.into())).unwrap();
    assert!((l.map.h[0] - 0.2126).abs() < 1e-6);
    assert!(l.notes.iter().any(|n| n.contains("luma")));
}

#[test]
fn other_sizes_are_resampled_to_a_square_power_of_two_and_say_so() {
    let img = image::GrayImage::from_fn(3, 2, |x, _| image::Luma([(x * 100) as u8]));
    let l = load(&write("g3x2.png", img.into())).unwrap();
    assert_eq!(l.map.side, 4);
    assert!(l.notes.iter().any(|n| n.contains("3 × 2 resampled")));
    // a ramp stays a ramp: rising along x, constant along y
    assert!(l.map.h[1] > l.map.h[0] && l.map.h[3] >= l.map.h[2] && l.map.h[4] == l.map.h[0]);
}

#[test]
fn bad_files_get_one_line_naming_the_file() {
    let dir = test_dir();
    std::fs::create_dir_all(&dir).unwrap();
    let (empty, text, cut) = (dir.join("empty.png"), dir.join("text.png"), dir.join("cut.png"));
    std::fs::write(&empty, b"").unwrap();
    std::fs::write(&text, b"not an image").unwrap();
    let good = std::fs::read(write("whole.png", image::GrayImage::new(8, 8).into())).unwrap();
    std::fs::write(&cut, &good[..good.len() / 2]).unwrap();
    let one = image::GrayImage::new(1, 5);
    let thin = write("thin.png", one.into());
    for (p, what) in [
        (&empty, "empty"),
        (&text, "not a PNG"),
        (&cut, "not a readable PNG"),
        (&thin, "at least 2 × 2"),
        (&dir.join("absent.png"), "cannot read"),
    ] {
        let e = load(p).err().unwrap_or_else(|| panic!("{} loaded", p.display()));
        assert!(e.contains(&p.display().to_string()) && e.contains(what) && !e.contains('\n'), "{e}");
    }
}
