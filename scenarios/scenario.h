#pragma once
// A scenario: everything one playback of Sylva needs (terrain, species, populations, camera and
// sun paths, shadow and render settings). Plain data with defaults; read from JSON by
// scenarios/scenario_loader.h, which rejects anything outside the ranges listed here.
//
// JSON format. Keys are the field names below (snake_case). Every section and every field is
// optional unless marked REQUIRED; an absent field keeps its default. Unknown keys are errors.
// Ranges are inclusive. Integers must be written as JSON integers (960, not 960.0).
// File paths are relative to the scenario file's folder (or absolute) and must name an existing
// file; the loaded scenario holds them as absolute paths.
//
//   name           string           default: the file name without extension
//   seed           integer          1            0 .. 2^64-1; seeds the plant generators and
//   placement resolution     [width, height]  [960, 540]   each 1 .. 16384 pixels frames integer 48
//   1 .. 1000000 fps            number           24           1 .. 1000; frame i is shown at time i
//   / fps world_offset   [x, y, z]        [0, 0, 0]    each -1e9 .. 1e9 m; added to every world
//   position
//                                                (stress-tests double-precision handling)
//   terrain {
//     size_m         number       400          1 .. 100000; square, centred on the origin
//     resolution     integer      129          2 .. 4097 vertices per side
//     height_m       number       25           0 .. 10000; peak-to-valley scale of the hills
//     octaves        integer      5            1 .. 16 noise octaves
//     frequency      number       0.008        0 .. 10 cycles per metre (lowest octave)
//     seed           integer      7            0 .. 2^64-1
//     ground_color   [r, g, b]    [0.32, 0.30, 0.18]  each 0 .. 1 (linear)
//     heightmap      file path    none         16-bit PNG or EXR, square (models/terrain/terrain.h
//                                              load_heightmap: 0..1 -> 0..height_m over size_m);
//                                              when set, resolution, octaves, frequency and
//                                              seed are ignored
//     tiles_per_side integer      1            1 .. 256; the ground mesh in n x n tiles (at most
//                                              resolution - 1 without a heightmap)
//     max_error_px   number       0.5          0 .. 64; each tile is drawn from the coarsest grid
//                                              of every 2^g-th sample whose height error shows
//                                              as at most this many pixels (geometric
//                                              mip-mapping; 0: every sample at any distance)
//   }
//   species        REQUIRED array of >= 1 {
//     name               string REQUIRED, non-empty, unique among species
//     generator          string     "broadleaf"  one of k_tree_generators
//     model              file path  none         a glTF file (.gltf or .glb) drawn instead of
//                                                the generator's plant
//     height_m           number     12           0.1 .. 150
//     reduced_distance_m number     60           0 .. 1000000; the reduced mesh is drawn beyond it
//     far_distance_m     number     200          0 .. 1000000; the far mesh is drawn beyond it;
//                                                must be >= reduced_distance_m
//     importance         number     1            0.01 .. 100; Deussen 2002 §4.3: multiplies the
//                                                importance of every part (above 1: kept
//                                                detailed longer under points_lines)
//     max_distance_m     number     1500         0 .. 1000000; not drawn beyond it as
//                                                mesh levels (points_lines draws to the far
//                                                plane); must be >= far_distance_m
//     octree_depth       integer    0            0 .. 3; Deussen 2002 §6.1 cells per plant
//     lighting           string     "scenario"   "scenario" (lod.lighting), "normal_mapped",
//                                                "pre_lit", "sh", "implicit" or "sh_implicit"
//                                                (see lod.lighting)
//     implicit           object     {}           Luft 2007, with lighting "implicit": {
//       generator_fraction number   1            0.001 .. 1; the foliage triangles that are
//                                                generators (§3.1)
//       rho_m            number     0            0 .. 1000; ρ (Eq. 2); 0: 0.2 x the foliage's
//                                                radius
//       tau              number     0            0 .. 1000; τ (Eq. 3); 0: a quarter of the
//                                                foliage's own median density
//       ka_min           number     0.3          0 .. 1; k_a,min (Eq. 4)
//       ambient_from     string     "depth"      Eq. 4's d_v: "depth" (below the iso-surface,
//                                                metres) or "density" (F(v), the paper's)
//       d_min            number     0            0 .. 1000; d_min (Eq. 4) for "density"; 0:
//                                                twice the foliage's median density less τ
//       depth_min_m      number     0            0 .. 1000; d_min (Eq. 4) for "depth"; 0: twice
//                                                the foliage's median depth
//       exponent         number     1            0.05 .. 20; n (Eq. 4)
//       blend            number     1            0 .. 1; 1: the iso-surface's normal, 0: the
//                                                original (§3.3)
//       population       boolean    false        §5: neighbouring implicit-lit plants darken
//                                                this species' plants too (kept per instance) }
//     ladder             array      none         this species' ladder (lod.representation
//                                                "ladder"), as lod.ladder; none: lod.ladder
//   }
//   populations    REQUIRED array of >= 1 {
//     species        string REQUIRED  the name of a species
//     count          integer REQUIRED 1 .. 10000000 plants requested
//     min_spacing_m  number     3            0 .. 1000
//     scale_min      number     0.8          0.01 .. 100; scale_min <= scale_max
//     scale_max      number     1.2          0.01 .. 100
//     area           [x0, z0, x1, z1]  default: the whole terrain [-size/2, -size/2, size/2,
//     size/2];
//                                      each -1e9 .. 1e9 m, x0 < x1 and z0 < z1
//     max_slope_deg  number     35           0 .. 90
//     min_altitude_m number     -1e9         -1e9 .. 1e9; no plants where the terrain is lower
//     max_altitude_m number     1e9          -1e9 .. 1e9; nor higher; must be >= min_altitude_m
//     placement      string     "poisson"    "poisson" (dart throwing), "jittered" (grid) or
//                                            "wang_tiles" (Behrendt 2005 §3.4: the plants of the
//                                            scenario's Wang tiling, wang_tiles below, at `count`
//                                            over the area's density; a tile type is the same
//                                            plants wherever it lies, so slope, altitude and
//                                            density rules cannot be given but at their defaults)
//     density_map    file path  none         greyscale PNG over the area (white: plants kept,
//                                            black: none; row 0 at z0); not with density
//     density {                 none         procedural density (models/terrain/density.h)
//       frequency    number     4            0.01 .. 1000 noise cycles across the area
//       coverage     number     0.5          0 .. 1 fraction of the area that is dense
//     }
//   }
//   camera {
//     near_m     number   0.3    0.001 .. 1000
//     far_m      number   3000   0.01 .. 10000000; must be > near_m
//     lod_scale  number   1      0.01 .. 100; multiplies every LOD switch distance
//     keyframes  array of >= 1, times strictly increasing; default: default_camera_keyframes()
//                (scenario_loader.h), a flight across the terrain over the whole playback {
//       t                   number REQUIRED  0 .. 1000000 seconds
//       position            [x, y, z] REQUIRED  each -1e9 .. 1e9 m
//       target              [x, y, z] REQUIRED  each -1e9 .. 1e9 m; must differ from position
//       fov_deg             number   55      5 .. 150 (vertical)
//       relative_to_terrain boolean  true    y of position and target are metres above the
//                                            terrain under them (else absolute world y)
//     }
//   }
//   sun {
//     keyframes  array of >= 1, times strictly increasing; default: one key (42, 135) {
//       t              number REQUIRED   0 .. 1000000 seconds
//       elevation_deg  number REQUIRED   -90 .. 90
//       azimuth_deg    number REQUIRED   0 .. 360
//     }
//     intensity      number  3   0 .. 1000000
//     turbidity      number  3   1.7 .. 10 (Preetham sky)
//     sky_intensity  number  1   0 .. 1000000; also scales the environment map's radiance
//   }
//   environment {  what lights the scene besides the sun (the sun stays a directional light)
//     map              file path  none  an HDR latitude-longitude map (.hdr or .exr, linear
//                                       float RGB, width = 2 x height; orientation in
//                                       lighting/environment_map.h: the image centre
//                                       is north, -z, the top row the zenith). When set, its
//                                       SH projection replaces the Preetham sky's (turbidity
//                                       then only colours the sun) and it is drawn as the sky;
//                                       it turns about the vertical with the sun: as the sun's
//                                       azimuth moves away from the first sun keyframe's, the
//                                       map turns by the same angle
//     map_rotation_deg number     0     -360 .. 360; turns the map about the vertical,
//                                       clockwise seen from above (as azimuth grows: 90 puts
//                                       the map's north at east); only with map
//   }
//   shadows {
//     cascades       integer 3     1 .. 4
//     resolution     integer 1024  256 .. 8192, a power of two
//     max_distance_m number  250   1 .. 100000
//     split_lambda   number  0.75  0 .. 1 (0: uniform splits, 1: logarithmic)
//   }
//   render {
//     shadows   boolean  true
//     exposure  number   1     0.001 .. 1000
//   }
//   wang_tiles {  Behrendt 2005 §3.4 (models/terrain/wang_tiles.h): the tiling every population
//                 with placement "wang_tiles" shares
//     tile_size_m  number   32    1 .. 10000; at least 5.41 x the min_spacing_m of each such
//                                 population (corner squares, edge strips and an interior)
//     colours      integer  2     2 .. 4 corner colours: colours^4 tiles
//   }
//   shells {      Behrendt 2005 §3.2-3.3, how the shell rung draws (passes/shell_pass.h)
//     slant            number   1     0 .. 4: f of the limited Eq. 2 (0: flat slices)
//     half_resolution  boolean  true  slices blended at half the frame's resolution
//     blending         string   "premultiplied"  or "standard" (measurement only: §3.3's pyramid
//                                    and blending with the standard equation, which pops)
//     lighting         string   "plants"  lit as the tiled plants are: by SH transfer baked into
//                                    the slices when every tiled species is SH-lit (Behrendt
//                                    2005 §4), else by the slices' normals (their length read as
//                                    Luft 2007's k_a when every tiled species is implicit-lit);
//                                    "normal_mapped" (measurement only): by the normals as plain
//                                    ones whatever the plants
//   }
//   eco_tiles {   Deussen 2002 §6.2 tiles for hierarchical culling (lod/eco_tiles.h)
//     enabled              boolean  true
//     max_plants_per_tile  integer  256   1 .. 1000000; a tile holding more is split in four
//   }
//   lod {         how plants are drawn at a distance
//     representation     string  "mesh_levels"  "mesh_levels" (the species' full, reduced and
//                                               far meshes by distance), "points_lines"
//                                               (Deussen 2002: prefixes of random-order
//                                               triangles, points and lines, §5) or
//                                               "billboard_clouds" (Behrendt 2005 §2.3: mesh
//                                               levels near, the billboard cloud beyond
//                                               cloud_distance_m, two crossed billboards beyond
//                                               the species' far_distance_m, each switch
//                                               cross-faded without sorting over ±15 %) or
//                                               "ladder" (each species' ladder of rungs by
//                                               projected size, faded across each band;
//                                               lod/ladder.h)
//     sample_distance_px number  1      0.05 .. 64; d', the screen distance between samples
//     splat_factor       number  1.3    1 .. 4; c_p of Eq. 1 (the paper: 1.2 .. 1.5)
//     splats             string  "soft" "soft" (Gaussian splats that each deposit the leaf area
//                                       they stand for, composited over a visibility pass;
//                                       our extension) or "opaque" (the paper's opaque squares)
//     fog_weighted_samples bool true   space a fogged plant's points d'/√T apart, T the share
//                                       of its colour the fog leaves (splats grow to match, at
//                                       most 4 d'; our extension); false: d' everywhere
//     primitive_budget   number  0      0 .. 1e9; with points_lines, d' is adapted every frame
//                                       to draw about this many triangle equivalents (points
//                                       and lines weighed by their cost; Deussen 2002 §5.4);
//                                       0: d' stays fixed
//     target_frame_ms    number  0      0 .. 100000; the same for a GPU frame time (not
//                                       deterministic: for walkthroughs); not with
//                                       primitive_budget. With representation "ladder" it
//                                       drives the auto ladder instead: the plants' budget
//                                       starts at plant_budget_ms (0: every plant on its
//                                       cheapest rung) and is adapted each frame to hold this
//                                       GPU time
//     cloud_distance_m   number  30     0.1 .. 100000; billboard_clouds: nearer than this (times
//                                       plant scale and lod_scale) plants are polygonal (the
//                                       paper's "about 30 m"); capped per species at 0.74 x
//                                       far_distance_m so the two fade bands never overlap
//     lighting           string  "normal_mapped"  how plants are lit (Behrendt 2005 §2.3, §4):
//                                       "normal_mapped" (every representation by its normals:
//                                       the mesh's, the samples', the cloud atlas's normal page),
//                                       "pre_lit" (billboard clouds take the atlas's page lit at
//                                       bake time with the plant's own shadows; meshes and
//                                       samples stay normal-lit) or "sh" (precomputed radiance
//                                       transfer: every representation lit by the same baked
//                                       SH transfer vectors, self-shadowing included) or
//                                       "implicit" (Luft 2007: normals realigned to the
//                                       foliage's implicit surface, the ambient darkened by its
//                                       density, baked into the model; species.implicit) or
//                                       "sh_implicit" (SH transfer baked from those normals, the
//                                       sky's light times k_a); a
//                                       species' own "lighting" overrides it
//     sh_bands           integer 3       2 .. 3; SH bands of the transfer vectors (4 or 9
//                                       coefficients) with lighting "sh"
//     sh_interreflection boolean false   with lighting "sh": add one diffuse bounce of the
//                                       plant's own light to its transfer (Sloan et al. 2002's
//                                       interreflected transfer; bakes about twice as long)
//     plant_budget_ms    number  0      0 .. 100000; with representation "ladder": every plant's
//                                       rung chosen each frame from tables measured per species
//                                       and rung (error against the full plant, and cost), so
//                                       that the plants' predicted cost stays within this many
//                                       ms (the auto ladder); 0: rungs switch by projected size
//     max_error          number  0      0 .. 1; with representation "ladder", instead of a
//                                       budget: every plant on the cheapest rung whose mean
//                                       colour error per plant pixel (of 1, in the same tables)
//                                       is at most this; not with plant_budget_ms or
//                                       target_frame_ms
//     gain_per_ms        number  0      0 .. 1e6; with representation "ladder": the auto ladder
//                                       buys a plant a dearer rung only where each ms of it puts
//                                       right at least this much error (the tables' colour
//                                       error summed over the plant's pixels: pixels' worth).
//                                       Alone it spends what each frame is worth (more where
//                                       plants are near and large, little where they are far);
//                                       with plant_budget_ms or target_frame_ms the budget also
//                                       caps it; not with max_error
//     lodf_slots         integer 32     1 .. 65536; plants a ladder with a "lodf" rung can
//                                       draw by LoDF at once (each slot holds the species'
//                                       cluster entities and indirect commands); a plant that
//                                       reaches the rung takes a free one and keeps it while it
//                                       stays; one without a free slot draws mesh_full
//     ladder             array   none   1 .. 8 rungs, nearest first, for representation
//                                       "ladder"; none: the papers' ladder (lod/ladder.h
//                                       papers_ladder). Each {
//       rung             string REQUIRED one of lod/ladder.h k_rung_names, each at most once
//       below_px         number  REQUIRED but on the first rung (which takes none); 0.01 .. 1e6:
//                                       the rung takes over below this projected height in
//                                       pixels; smaller than the rung before's
//       band             number  0.15   0 .. 0.9; the handover fades over below_px x (1 ± band);
//                                       bands may not overlap; not on the first rung
//     }
//   }
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/camera_path.h"

namespace sylva {

// The plant generator presets a species may name (models/generate/tree_generator.h implements each).
inline constexpr std::array<std::string_view, 7> k_tree_generators = {
    "broadleaf", "broadleaf_hd", "conifer", "shrub", "grass", "flower", "fern"};

// How a population is spread (models/terrain/placement.h placement_rules::poisson).
inline constexpr std::array<std::string_view, 3> k_placement_modes = {"poisson", "jittered", "wang_tiles"};

struct terrain_settings {
    double size_m = 400.0;
    std::uint32_t resolution = 129;  // vertices per side
    float height_m = 25.0f;
    std::uint32_t octaves = 5;
    float frequency = 0.008f;  // cycles per metre
    std::uint64_t seed = 7;
    glm::vec3 ground_color{0.32f, 0.30f, 0.18f};
    std::string heightmap;  // absolute path, empty: noise terrain
    std::uint32_t tiles_per_side = 1;
    float max_error_px =
        0.5f;  // components/ground_tile.h; resources/ground_lod.h k_ground_error_px
    bool operator==(const terrain_settings&) const = default;
};

// One rung of a ladder (lod/ladder.h), nearest first: `rung` is one of lod/ladder.h's
// k_rung_names; every rung but the first takes over below `below_px` of projected size, across a
// band of ±`band` of it. `shadow`: another of the ladder's rungs its plants cast their shadows
// as ("": their own).
struct ladder_step_settings {
    std::string rung;
    float below_px = 0.0f;  // 0: not given (the first rung takes none)
    float band = 0.15f;
    std::string shadow = {};
    bool operator==(const ladder_step_settings&) const = default;
};

inline constexpr std::array<std::string_view, 2> k_ambient_sources{"depth", "density"};

// Luft 2007 (models/bake/implicit_illumination.h): a species' implicit-surface illumination,
// baked into its model when its lighting is "implicit". 0 for rho_m, tau, d_min and depth_min_m:
// derived from the model's foliage (its size, its own density and depth).
struct implicit_lighting_settings {
    // §3.1: the share of foliage triangles that are generators. The paper takes one per primitive
    // and offers a random fraction as a shortcut for speed; the bake needs none (broadleaf_hd's
    // whole bake about 0.5 s with every triangle, 0.2-0.3 s with a quarter), and a quarter made the
    // field noisier: k_a ranked ray-cast occlusion worse on every model (`sylva implicit-ao`:
    // broadleaf 0.698 against 0.642, conifer 0.701 against 0.676) and forest's crowns kept more
    // noise (`sylva implicit-look forest`: -41.5 % against -39.2 %).
    float generator_fraction = 1.0f;
    float rho_m = 0.0f;                // ρ (Eq. 2)
    float tau = 0.0f;                  // τ (Eq. 3)
    float ka_min = 0.3f;               // k_a,min (Eq. 4)
    // Eq. 4's d_v (models/bake/implicit_illumination.h, ambient_source): "depth" below the
    // iso-surface (ranks ray-cast occlusion better) or "density", the paper's F(v).
    std::string ambient_from = "depth";  // one of k_ambient_sources
    float d_min = 0.0f;                  // d_min (Eq. 4) for "density"
    float depth_min_m = 0.0f;            // d_min (Eq. 4) for "depth", in metres
    float exponent = 1.0f;             // n (Eq. 4)
    float blend = 1.0f;                // 1: the iso-surface's normal; 0: the original (§3.3)
    // §5: this species' plants are darkened by their neighbours' density too (the field of the
    // population, setup/population_ambient.h); every implicit-lit plant counts as a neighbour.
    bool population = false;
    bool operator==(const implicit_lighting_settings&) const = default;
};

struct species_settings {
    std::string name;
    std::string generator = "broadleaf";
    std::string model;  // absolute path of a glTF file, empty: the generator's plant
    float height_m = 12.0f;
    float reduced_distance_m = 60.0f;
    float far_distance_m = 200.0f;
    float max_distance_m = 1500.0f;
    float importance = 1.0f;
    std::uint32_t octree_depth = 0;
    std::string lighting = "scenario";  // one of k_species_lightings
    implicit_lighting_settings implicit;     // with lighting "implicit" (or the scenario's)
    std::vector<ladder_step_settings> ladder;  // empty: the lod section's
    bool operator==(const species_settings&) const = default;
};

struct procedural_density_settings {
    bool enabled = false;  // true when the scenario gives "density"
    float frequency = 4.0f;
    float coverage = 0.5f;
    bool operator==(const procedural_density_settings&) const = default;
};

struct population_settings {
    std::string species;
    std::uint32_t count = 0;
    float min_spacing_m = 3.0f;
    float scale_min = 0.8f;
    float scale_max = 1.2f;
    // x0, z0, x1, z1 in metres. This default is the default terrain's extent; the loader
    // replaces it with the scenario's own terrain extent when "area" is absent.
    std::array<double, 4> area{-200.0, -200.0, 200.0, 200.0};
    float max_slope_deg = 35.0f;
    float min_altitude_m = -1e9f;
    float max_altitude_m = 1e9f;
    std::string placement = "poisson";  // one of k_placement_modes
    std::string density_map;            // absolute path, empty: none
    procedural_density_settings density;
    bool operator==(const population_settings&) const = default;
};

// A camera keyframe as the scenario states it. The key is kept whole (the camera path's own
// type) and the flag says how to read its heights: when above_terrain is true, key.position.y
// and key.target.y are metres above the terrain under them and are resolved to world heights
// once the terrain exists (setup/spawn_scenario.cpp).
struct scenario_camera_key {
    camera_keyframe key;
    bool above_terrain = true;

    friend bool operator==(const scenario_camera_key& a, const scenario_camera_key& b) {
        return a.key.time_s == b.key.time_s && a.key.position == b.key.position &&
               a.key.target == b.key.target && a.key.fov_deg == b.key.fov_deg &&
               a.above_terrain == b.above_terrain;
    }
};

struct camera_settings {
    float near_m = 0.3f;
    float far_m = 3000.0f;
    float lod_scale = 1.0f;
    std::vector<scenario_camera_key> keyframes;  // the loader always leaves >= 1
    bool operator==(const camera_settings&) const = default;
};

struct sun_keyframe {
    double t = 0.0;  // seconds
    float elevation_deg = 42.0f;
    float azimuth_deg = 135.0f;
    bool operator==(const sun_keyframe&) const = default;
};

struct sun_settings {
    std::vector<sun_keyframe> keyframes{sun_keyframe{}};
    float intensity = 3.0f;
    float turbidity = 3.0f;
    float sky_intensity = 1.0f;
    bool operator==(const sun_settings&) const = default;
};

struct environment_settings {
    std::string map;  // absolute path, empty: the analytic (Preetham) sky
    float map_rotation_deg = 0.0f;
    bool operator==(const environment_settings&) const = default;
};

struct shadow_settings {
    std::uint32_t cascades = 3;
    std::uint32_t resolution = 1024;  // texels per side of each cascade
    float max_distance_m = 250.0f;
    float split_lambda = 0.75f;
    bool operator==(const shadow_settings&) const = default;
};

// How plants and ground are shaded (render.style): "photo", "toon" (Luft 2007 §4's
// non-photorealistic use: shading quantised into bands, Decaudin 1996) or "lines" (ink lines
// where the normal or depth buffer jumps, Saito & Takahashi 1990; Luft 2007 Figure 7).
inline constexpr std::array<std::string_view, 3> k_styles{"photo", "toon", "lines"};

struct render_settings {
    bool shadows = true;
    float exposure = 1.0f;
    std::string style = "photo";  // one of k_styles
    bool operator==(const render_settings&) const = default;
};

struct wang_tile_settings {
    double tile_size_m = 32.0;
    std::uint32_t colours = 2;
    bool operator==(const wang_tile_settings&) const = default;
};

inline constexpr std::array<std::string_view, 2> k_shell_blendings{"premultiplied", "standard"};
inline constexpr std::array<std::string_view, 2> k_shell_lightings{"plants", "normal_mapped"};

struct shell_settings {
    double slant = 1.0;  // Behrendt 2005 Eq. 2's f; the paper's 1
    bool half_resolution = true;
    std::string blending = "premultiplied";  // one of k_shell_blendings
    std::string lighting = "plants";         // one of k_shell_lightings
    bool operator==(const shell_settings&) const = default;
};

struct eco_tile_settings {
    bool enabled = true;
    std::uint32_t max_plants_per_tile = 256;
    bool operator==(const eco_tile_settings&) const = default;
};

// The representations `lod.representation` may name.
inline constexpr std::array<std::string_view, 4> k_lod_representations{"mesh_levels", "points_lines",
                                                                        "billboard_clouds", "ladder"};
// The lighting variants `lod.lighting` may name (Behrendt 2005 §2.3 and §4).
inline constexpr std::array<std::string_view, 5> k_lightings{"normal_mapped", "pre_lit", "sh", "implicit",
                                                             "sh_implicit"};
// How `lod.splats` may draw point samples (lod/point_line_lod.h splat_style).
inline constexpr std::array<std::string_view, 2> k_splat_styles{"soft", "opaque"};
// A species' `lighting`: "scenario" takes the lod section's.
inline constexpr std::array<std::string_view, 6> k_species_lightings{"scenario", "normal_mapped", "pre_lit",
                                                                     "sh",       "implicit",      "sh_implicit"};

struct lod_settings {
    std::string representation = "mesh_levels";
    float sample_distance_px = 1.0f;
    float splat_factor = 1.3f;
    std::string splats = "soft";  // one of k_splat_styles
    bool fog_weighted_samples = true;
    double primitive_budget = 0.0;
    double target_frame_ms = 0.0;
    float cloud_distance_m = 30.0f;
    std::string lighting = "normal_mapped";  // one of k_lightings
    std::uint32_t sh_bands = 3;
    bool sh_interreflection = false;
    std::vector<ladder_step_settings> ladder;  // empty: the papers' ladder (lod/ladder.h)
    double plant_budget_ms = 0.0;  // ladder: rungs chosen by measured tables within this cost
    double max_error = 0.0;        // ladder: the cheapest rung within this error per plant pixel
    double gain_per_ms = 0.0;  // ladder: a dearer rung only where a ms of it buys this much error
    std::uint32_t lodf_slots = 32;  // plants on the LoDF rung at once (resources/lodf_slots.h)
    bool operator==(const lod_settings&) const = default;
};

struct scenario {
    std::string name;
    std::string source;  // the file it came from, or "embedded:scenarios/default.json"
    std::uint64_t seed = 1;
    std::uint32_t width = 960;
    std::uint32_t height = 540;
    std::uint32_t frames = 48;
    double fps = 24.0;
    glm::dvec3 world_offset{0.0};
    terrain_settings terrain;
    std::vector<species_settings> species;
    std::vector<population_settings> populations;
    camera_settings camera;
    sun_settings sun;
    environment_settings environment;
    shadow_settings shadows;
    render_settings render;
    wang_tile_settings wang_tiles;
    shell_settings shells;
    eco_tile_settings eco_tiles;
    lod_settings lod;
    bool operator==(const scenario&) const = default;
};

}  // namespace sylva
