#include "systems/render/scene_textures.h"

#include <array>
#include <glm/vec4.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/bake/crossed_billboard.h"
#include "systems/render/textures.h"

namespace sylva::render {
namespace {

// transfer.glsl's species_block, by texture layer: each species' sphere (centre height, radius
// around every representation) for shadow lookups outside the plant's own volume, and its first
// transfer-page layer. Only species lit by transfer read it, so only they count against its size.
gl_buffer make_species_block(const scene_assets& assets) {
    constexpr std::size_t k_spheres = scene_textures::k_max_species_spheres;
    std::array<glm::vec4, k_spheres> spheres{};
    for (const species_entry& e : assets.library.species) {
        if (!uses_transfer(e.lighting)) continue;
        if (e.texture_layer >= float(k_spheres))
            throw std::runtime_error("renderer: species '" + e.name +
                                     "' is lit by SH transfer, which supports the first " +
                                     std::to_string(k_spheres) + " species of a scene only");
        spheres[std::size_t(e.texture_layer)] =
            glm::vec4(e.center_height, e.transfer_radius, e.transfer_layer, 0.0f);
    }
    // Billboards read their transfer from pages: a scene that lights them by transfer must have
    // them.
    for (std::size_t i = 0; i < assets.meshes.size() && i < assets.library.meshes.size(); ++i) {
        if (!uses_transfer(assets.library.meshes[i].lighting) ||
            assets.meshes[i].submeshes.empty())
            continue;
        const material_kind m = assets.meshes[i].submeshes[0].material;
        if ((is_billboard(m) && assets.billboard_transfer.empty()) ||
            (m == material_kind::billboard_cloud && assets.cloud_transfer.empty()))
            throw std::logic_error("renderer: mesh " + std::to_string(i) +
                                   " is lit by SH transfer but has no transfer pages");
    }
    gl_buffer block = make_buffer();
    glNamedBufferStorage(block.id(), sizeof(spheres), spheres.data(), 0);
    return block;
}

}  // namespace

scene_textures::scene_textures(const scene_assets& assets) {
    leaf = make_texture_array(assets.leaf_textures, false, true);
    bark = make_texture_array(assets.bark_textures, true);
    ground = make_texture_array(std::span(&assets.ground_texture, 1), true);
    if (assets.terrain.resolution >= 2) {
        const heightfield& field = assets.terrain;
        const auto n = std::size_t(field.resolution);
        std::vector<float> xz(n * n * 2);
        for (std::size_t r = 0; r < n; ++r)
            for (std::size_t c = 0; c < n; ++c) {
                // The vertex normal of the grid vertex there (models/terrain/terrain.cpp).
                const glm::vec3 normal =
                    field.normal_at(double(c) * field.spacing() - 0.5 * field.size_m,
                                    double(r) * field.spacing() - 0.5 * field.size_m);
                xz[2 * (r * n + c)] = normal.x;
                xz[2 * (r * n + c) + 1] = normal.z;
            }
        ground_normal = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(ground_normal.id(), 1, GL_RG32F, GLsizei(n), GLsizei(n));
        glTextureSubImage2D(ground_normal.id(), 0, 0, 0, GLsizei(n), GLsizei(n), GL_RG, GL_FLOAT,
                            xz.data());
        glTextureParameteri(ground_normal.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(ground_normal.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(ground_normal.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(ground_normal.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        uploaded_bytes += xz.size() * sizeof(float);
    }
    if (!assets.billboard_albedo.empty()) {
        // The bake's atlases keep each image's coverage apart; an atlas made by hand (tests) is
        // one image.
        const image_rgba8& first = assets.billboard_albedo[0];
        std::vector<std::uint32_t> columns = crossed_billboard_atlas_columns(first.height);
        if (columns.back() != first.width) columns.clear();
        billboard_albedo = make_texture_array(assets.billboard_albedo, false, true, columns);
        billboard_normal = make_texture_array(assets.billboard_normal, false);
        if (!assets.billboard_transfer.empty())
            billboard_transfer = make_texture_array(assets.billboard_transfer, false);
    }
    if (!assets.cloud_albedo.empty()) {
        // The colour page's alpha is filtered plainly: the fade threshold reads the gaussian
        // in it. The normal page's alpha is the coverage the alpha test reads, kept per mip.
        // Pre-lit clouds read the page lit at bake time in its place (same layout and alpha).
        cloud_albedo = make_texture_array(assets.cloud_albedo, false);
        cloud_normal = make_texture_array(assets.cloud_normal, false, true);
        if (!assets.cloud_pre_lit.empty())
            cloud_pre_lit = make_texture_array(assets.cloud_pre_lit, false);
        if (!assets.cloud_transfer.empty())
            cloud_transfer = make_texture_array(assets.cloud_transfer, false);
    }
    species_block = make_species_block(assets);
    for (const auto* images :
         {&assets.leaf_textures, &assets.bark_textures, &assets.billboard_albedo,
          &assets.billboard_normal, &assets.cloud_albedo, &assets.cloud_normal,
          &assets.cloud_pre_lit, &assets.cloud_transfer, &assets.billboard_transfer})
        for (const auto& image : *images) uploaded_bytes += image.texels.size();
    uploaded_bytes += assets.ground_texture.texels.size();
}

}  // namespace sylva::render
