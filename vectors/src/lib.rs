//! This is the bumprtl reference model: for every hardware unit, a float `ideal()` (the mathematics the hardware
//! approximates) and a bit-exact `exact()` in integers of exactly the rtl widths, plus the vector generator.
//! It has no rust-hdl dependency: the rtl is checked against it, never the other way round.

/// Units more than one family uses, the fixed-point steps, and normals from heights.
pub mod shared {
    pub mod bilinear;
    pub mod blend;
    pub mod dot3;
    pub mod fixed;
    pub mod gloss;
    pub mod normal_map;
    pub mod normalise;
}

/// US 6,819,319's second embodiment: Cartesian texels (and their encoders), per-pixel lights.
pub mod cartesian {
    pub mod cart_decode;
    pub mod cart_decode_hemi_oct;
    pub mod cart_encode;
    pub mod cart_f32;
    pub mod cart_pipeline;
    pub mod cart_surface;
    pub mod cart_tex;
    pub mod light_iter;
}

/// US 6,819,319's first embodiment (FIG. 3): polar texels (and their encoder), one light per surface.
pub mod polar {
    pub mod cos_sign;
    pub mod polar_encode;
    pub mod polar_pipeline;
    pub mod polar_shade;
    pub mod polar_tex;
    pub mod power;
    pub mod sincos;
}

/// US 2004/0207631: normals generated from height maps on the texture filter's bilinear units.
pub mod height {
    pub mod blend_adjust;
    pub mod blinn_pipeline;
    pub mod filters;
    pub mod height_addr;
    pub mod height_fetch;
    pub mod height_normal;
    pub mod height_pipeline;
    pub mod replicate;
    pub mod surfaces;
    pub mod tangent;
    pub mod texture_filter;
}

/// Tarini et al.: quantized normal maps and per-frame colour tables.
pub mod palette {
    pub mod palette_lookup;
    pub mod palette_pipeline;
    pub mod palette_pipeline_shared;
    pub mod palette_tex;
    pub mod plane_fit;
    pub mod quantize;
    pub mod table_builder;
    pub mod tables;
}

/// The texture unit in front of every family: level of detail, address, the map memory and its fetch.
pub mod texture {
    pub mod front;
    pub mod lod;
    pub mod tex_addr;
    pub mod tex_fetch;
    pub mod textured;
}

pub mod csv;
pub mod stats;
pub mod unit;

// every unit also at the crate root, by its own name, whatever its family
pub use cartesian::{
    cart_decode, cart_decode_hemi_oct, cart_encode, cart_f32, cart_pipeline, cart_surface, cart_tex, light_iter,
};
pub use height::{
    blend_adjust, blinn_pipeline, height_addr, height_fetch, height_normal, height_pipeline, replicate, tangent,
    texture_filter,
};
pub use palette::{palette_lookup, palette_pipeline, palette_pipeline_shared, palette_tex, table_builder};
pub use polar::{cos_sign, polar_encode, polar_pipeline, polar_shade, polar_tex, power, sincos};
pub use shared::{bilinear, blend, dot3, fixed, gloss, normal_map, normalise};
pub use texture::{lod, tex_addr, tex_fetch, textured};
pub use unit::{Port, UnitModel};
