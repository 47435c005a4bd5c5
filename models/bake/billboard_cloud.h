#pragma once
// Billboard clouds for plants, Behrendt 2005 §2: the plant's triangles are clustered
// (models/bake/vertex_clustering.h), each cluster gets a minimum-volume box
// (models/bake/oriented_box.h) and one to three billboards by the shape of that box, and both sides
// of every billboard are rendered from the cluster's own triangles (models/bake/billboard_bake.h)
// into one texture atlas.
//
// The mesh: per billboard two one-sided quads in the same plane, the front side and the back
// side (back_side()), each with its own image, the plane's normal toward its viewer and
// counter-clockwise winding seen from that viewer, all in one material_kind::billboard sub-mesh.
// Drawn with back faces culled, each side shows only to its own viewer (true two-sided
// billboards): the runtime relabels the sub-mesh material_kind::billboard_cloud and draws it so
// (setup/build_scene_assets.cpp, systems/render/passes/cloud_draw.cpp). Drawn double-sided, as
// crossed billboards are, the two quads of a billboard share a depth and either may win; the
// loser's image is the other's mirror with the same silhouette, so that degrades to the crossed
// billboard's look, not to holes.
//
// The atlas (one layout, several pages of the same size):
//
//   +------------------------------------------------+  each billboard owns one rectangle,
//   | +-------+-------+   +---+---+                  |  its front image on the left half and
//   | | front | back  |   | f | b |  ...             |  its back image on the right half, rows
//   | +-------+-------+   +---+---+                  |  top (along axis_v) to bottom; gutters of
//   |   ...                                          |  `gutter` texels between rectangles hold
//   +------------------------------------------------+  their edge colours at alpha 0
//
//   page 0  albedo: rgb the mean texture colour (unlit), a = coverage x gaussian (see below)
//   page 1  normal: rgb model-space normal n * 0.5 + 0.5, a = coverage alone
//   page 2  pre-lit: rgb the albedo lit once at bake time by one light including the plant's
//           own shadows (Behrendt 2005 §2.3's first variant; light_factor()), a as page 0's
//   transfer pages (only when baked with the plant's radiance transfer, Behrendt 2005 §4: "we
//           store the Gouraud-interpolated vectors in an extra texture"): k_transfer_pages
//           more pages of the same layout (models/bake/transfer_pages.h); each billboard side's
//           texels hold the transfer of the side its own viewer sees first.
//
// Sort-free fading (Behrendt 2005 §2.3): "We multiply the alpha channel of the billboard texture
// with a gauss curve in pre-processing"; at run time a fragment is discarded below a threshold
// that grows with distance, and survivors are drawn opaque, so billboards shrink toward their
// centres and vanish without sorting. The paper gives no width; here the curve is
// g = exp(-(x² + y²) / (2 σ²)) over the billboard with x, y in [-1, 1] from its centre to its
// edges and σ = gaussian_sigma (default 1: 0.61 at the middle of an edge, 0.37 at a corner).
// Near the viewer the renderer can alpha-test the normal page's alpha (plain coverage) instead.
#include <array>
#include <cstdint>
#include <vector>

#include "models/bake/atlas_packing.h"
#include "models/bake/billboard_bake.h"
#include "models/image/image.h"
#include "models/mesh.h"
#include "models/bake/oriented_box.h"
#include "models/plant_model.h"
#include "models/bake/radiance_transfer.h"
#include "models/bake/transfer_pages.h"
#include "models/bake/vertex_clustering.h"

namespace sylva {

// Bump whenever the clustering, the boxes, the billboard rule, the bake or the layout change
// what a bake produces.
constexpr std::uint32_t k_billboard_cloud_format =
    5;  // 2: the pre-lit page; 3: transfer pages; 4: their background; 5: k_a on the pre-lit page

// Behrendt 2005 §2.2: "We found that f = 0.5 produces visibly pleasing results."
constexpr float k_billboard_shape_factor = 0.5f;

// Which faces of a box, sides a >= b >= c, get a billboard through the box's centre.
enum class box_face : std::uint8_t {
    ab,  // parallel to the two longest sides
    ac,
    bc,  // across the longest side
};

// Behrendt 2005 §2.2: "If √(a·b) > f·c for the three sides a, b, c then a billboard parallel to
// a and b is generated." Applied to each of the three pairs of sides against the remaining one,
// this is the paper's classification: two long sides and a short one give one billboard (ab);
// one long side gives two crossed billboards (ab, ac); roughly equal sides give three (ab, ac,
// bc). With a >= b >= c the tests are nested (bc passing implies ac, which implies ab whenever
// a·b > 0), so the result is always a prefix of {ab, ac, bc}. `sides` must be sorted descending
// and non-negative; throws std::invalid_argument naming them otherwise.
std::vector<box_face> billboard_faces(glm::vec3 sides, float f = k_billboard_shape_factor);

enum class cloud_atlas_page : std::uint32_t { albedo = 0, normal = 1, pre_lit = 2 };
constexpr std::uint32_t k_cloud_atlas_pages = 3;

struct billboard_cloud_settings {
    // target_clusters 0 (the default here): default_cluster_target(model).
    clustering_settings clustering{clustering_method::automatic, 0};
    float shape_factor = k_billboard_shape_factor;
    std::uint32_t atlas_width = 1024;  // 1024 x 512 RGBA8: 2 MiB colour, 2 MiB normals
    std::uint32_t atlas_height = 512;
    std::uint32_t gutter = 2;          // texels between rectangles: clean filtering and one mip
    std::uint32_t supersampling = 3;   // s x s subsamples per texel
    std::uint32_t max_side_texels = 256;  // per billboard side
    float gaussian_sigma = 1.0f;       // see the header comment
    // The pre-lit page's light (Behrendt 2005 §2.3: "created for a single light-position
    // including all shadows"): direction toward it in model space, and the share of the light
    // that reaches shadowed and turned-away surfaces (sky light) -- see light_factor().
    glm::vec3 pre_light_direction{0.35f, 0.8f, 0.45f};  // normalised when used
    float pre_light_ambient = 0.3f;
    std::uint32_t pre_light_map_size = 512;  // the plant's depth seen from the light, texels a side
    min_box_settings box;
};

struct cloud_billboard {
    billboard_plane plane;  // the front side; back_side(plane) is the other
    std::uint32_t cluster = 0;
    box_face face = box_face::ab;
    atlas_rect rect;  // both sides: front in the left half, back in the right half
};

struct cloud_cluster {
    oriented_box box;        // minimum-volume box of the cluster's vertices, axes sorted a >= b >= c
    float pca_volume = 0.0f;  // volume of its PCA box, for the comparison the paper makes
    std::uint32_t triangles = 0;
    bool foliage = false;  // most of its triangles are leaves (leaf or billboard material)
};

struct billboard_cloud {
    mesh_data mesh;  // two quads per billboard, in billboard order: front then back
    std::vector<cloud_billboard> billboards;
    std::vector<cloud_cluster> clusters;
    clustering_method method = clustering_method::kmeans;  // what the clustering used
    int branching_level = -1;
    std::uint32_t atlas_width = 0;
    std::uint32_t atlas_height = 0;
    std::array<image_rgba8, k_cloud_atlas_pages> pages;  // cloud_atlas_page order
    std::vector<image_rgba8> transfer_pages;             // k_transfer_pages, or none (see above)
    float texels_per_metre = 0.0f;  // the density every billboard was baked at

    const image_rgba8& page(cloud_atlas_page p) const { return pages[std::size_t(p)]; }
    std::size_t atlas_bytes() const;
};

// The clusters and billboards of a cloud, before any texture is baked: the geometry the atlas
// is then filled for. Exposed for tests and measurements (box volumes, billboard counts).
struct billboard_cloud_layout {
    triangle_clusters clustering;
    std::vector<cloud_cluster> clusters;
    std::vector<cloud_billboard> billboards;  // rect not yet set
};
billboard_cloud_layout plan_billboard_cloud(const plant_model& model, const billboard_cloud_settings& settings = {});

// Bakes the cloud of lods[0] with the model's leaf and bark textures. Deterministic: the same
// model and settings give byte-identical results on any thread count (billboards are baked in
// parallel, each into its own image, and copied into the atlas in billboard order). Throws
// std::invalid_argument naming the setting for a zero atlas, supersampling outside 1..16, a
// shape factor or sigma that is not positive and finite, or a model with no triangles, and
// std::runtime_error when even 2-texel billboards do not fit the atlas.
// With `transfer` (lods[0]'s, one receiver per vertex) the transfer pages are baked too.
billboard_cloud bake_billboard_cloud(const plant_model& model,
                                     const billboard_cloud_settings& settings = {},
                                     const radiance_transfer* transfer = nullptr);

// The normal page in the tangent space of each billboard side, for formats that want it (glTF):
// x along the side's axis_u, y along its axis_v (the image's up), z its normal toward its viewer
// (glTF's "+X right, +Y up, +Z toward the viewer"), encoded n * 0.5 + 0.5, alpha kept; texels of
// no billboard are the flat (0, 0, 1).
image_rgba8 tangent_space_normal_page(const billboard_cloud& cloud);

// The pre-lit page's light factor for a surface of unit normal n (turned toward its viewer)
// lit from unit direction l, `visible` the share of the light the plant's own parts do not
// block (0..1): k_a·ambient + (1 - ambient)·visible·(max(n·l, 0) + 0.35·max(-n·l, 0)), the second
// term the light a leaf transmits when lit from behind, as the leaf shader has it. k_a is Luft
// 2007's ambient coefficient (Eq. 1: the ambient term is k_a·I_a; Eq. 4 gives k_a), 1 for a plain
// model, so the pre-lit page of an implicit-lit plant is darker inside its crown as its meshes are.
float light_factor(glm::vec3 n, glm::vec3 l, float visible, float ambient, float ka = 1.0f);

// The plant's height (lods[0] vertices, y extent); 4 m and above counts as a tree below.
float plant_height(const plant_model& model);

// The target cluster count by the paper's ranges (Behrendt 2005 §2.1: 50-200 billboards for
// trees, 20-100 for smaller plants, one to three billboards per cluster): 60 for a tree, 25
// below.
std::uint32_t default_cluster_target(const plant_model& model);

// Settings for the bake cache and `sylva export-cloud`: that target, and the atlas by size:
// 1024 x 512 for a tree (2 MiB colour + 2 MiB normals; Behrendt 2005 §2.3 quotes about 1 MB
// colour and 2-5 MB with normals or SH), 512 x 256 for a small plant (1 MiB in all).
billboard_cloud_settings default_billboard_cloud_settings(const plant_model& model);

}  // namespace sylva
