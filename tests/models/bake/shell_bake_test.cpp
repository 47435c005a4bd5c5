// Behrendt 2005 §3.1 (models/bake/shell_bake.h): a tile's plants cut into slabs and rendered
// from above, by hand on leaf quads, and on a generated plant.
#include "models/bake/shell_bake.h"

#include <gtest/gtest.h>

#include "lighting/transfer_rotation.h"
#include "models/bake/transfer_pages.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

image_rgba8 solid(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    image_rgba8 image;
    image.width = image.height = 2;
    for (int i = 0; i < 4; ++i)
        for (std::uint8_t v : {r, g, b, std::uint8_t(255)}) image.texels.push_back(v);
    return image;
}

// A horizontal leaf square at height y over [x0, x1] x [z0, z1], facing up.
void add_leaf(mesh_data& mesh, float x0, float x1, float z0, float z1, float y) {
    const auto base = std::uint32_t(mesh.vertices.size());
    for (const auto& [x, z] : {std::pair{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}})
        mesh.vertices.push_back({{x, y, z}, {0.0f, 1.0f, 0.0f}, {0.5f, 0.5f}});
    const auto first = std::uint32_t(mesh.indices.size());
    mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    mesh.submeshes.push_back({first, 6, material_kind::leaf});
}

shell_bake_settings exact(std::uint32_t texels, std::uint32_t slices, float height) {
    shell_bake_settings s;
    s.texels = texels;
    s.slices = slices;
    s.height_m = height;
    s.supersampling = 2;
    s.blur_texels = 0.0f;
    s.margin_texels = 1;
    return s;
}

// A 4 m tile, 8 texels of 0.5 m, 4 slabs of 1 m: a leaf over [1, 3]² at 2.5 m lands in slab 2,
// on texels 2..5 in x and z, opaque; every other slab and texel is empty.
TEST(shell_bake, a_leaf_lands_in_its_slab_and_on_its_texels) {
    mesh_data model;
    add_leaf(model, -1.0f, 1.0f, -1.0f, 1.0f, 2.5f);
    const image_rgba8 green = solid(0, 200, 0);
    const image_rgba8 bark = solid(90, 60, 30);
    const shell_species species[] = {{&model, &green, &bark}};
    shell_plant plant;
    plant.where.xz = {2.0, 2.0};
    const shell_stack stack = bake_shell_stack(species, std::span(&plant, 1), 4.0, exact(8, 4, 4.0f));
    ASSERT_EQ(stack.colour.size(), 4u);
    EXPECT_FLOAT_EQ(stack.slice_height_m, 1.0f);
    for (std::uint32_t k = 0; k < 4; ++k)
        for (std::uint32_t z = 0; z < 8; ++z)
            for (std::uint32_t x = 0; x < 8; ++x) {
                const bool inside = k == 2 && x >= 2 && x <= 5 && z >= 2 && z <= 5;
                const std::uint8_t* c = stack.colour[k].at(x, z);
                EXPECT_EQ(c[3], inside ? 255 : 0) << k << " " << x << " " << z;
                EXPECT_EQ(c[1], inside ? 200 : 0);
                if (inside) {
                    EXPECT_GT(stack.normal[k].at(x, z)[1], 250) << "the leaf faces up";
                }
            }
}

// Within a slab the higher surface is what is seen from above; a neighbour's plant that reaches
// across the tile's border is baked where it reaches in; a yaw turns the plant as the renderer does.
TEST(shell_bake, the_higher_surface_wins_and_neighbours_reach_in) {
    mesh_data low;
    add_leaf(low, -1.0f, 1.0f, -1.0f, 1.0f, 0.2f);
    mesh_data high;
    add_leaf(high, -0.5f, 0.5f, -0.5f, 0.5f, 0.8f);
    const image_rgba8 red = solid(200, 0, 0);
    const image_rgba8 blue = solid(0, 0, 200);
    const image_rgba8 bark = solid(90, 60, 30);
    const shell_species species[] = {{&low, &red, &bark}, {&high, &blue, &bark}};
    std::vector<shell_plant> plants(3);
    plants[0] = {0, {}};
    plants[0].where.xz = {2.0, 2.0};
    plants[1] = {1, {}};
    plants[1].where.xz = {2.0, 2.0};
    plants[2] = {0, {}};
    plants[2].where.xz = {-0.5, 2.0};  // a neighbour's, over x in [-1.5, 0.5]
    const shell_stack stack = bake_shell_stack(species, plants, 4.0, exact(8, 1, 1.0f));
    EXPECT_EQ(stack.colour[0].at(4, 4)[2], 200) << "blue (higher) over red at the centre";
    EXPECT_EQ(stack.colour[0].at(4, 4)[0], 0);
    EXPECT_EQ(stack.colour[0].at(2, 2)[0], 200) << "red where only the low leaf is";
    EXPECT_EQ(stack.colour[0].at(0, 4)[3], 255) << "the neighbour's leaf reaches texel 0";
    EXPECT_EQ(stack.colour[0].at(1, 4)[3], 0);
    // A quarter turn maps +x to −z: a leaf over x in [0, 1], z in [-0.5, 0.5] turned by 90°
    // covers x in [-0.5, 0.5], z in [-1, 0] around the plant, so texels 3..4 in x, 2..3 in z.
    mesh_data strip;
    add_leaf(strip, 0.0f, 1.0f, -0.5f, 0.5f, 0.5f);
    const shell_species one[] = {{&strip, &red, &bark}};
    shell_plant turned{0, {}};
    turned.where.xz = {2.0, 2.0};
    turned.where.yaw = 1.5707963f;
    const shell_stack t = bake_shell_stack(one, std::span(&turned, 1), 4.0, exact(8, 1, 1.0f));
    EXPECT_EQ(t.colour[0].at(4, 2)[3], 255) << "x' = c x + s z, z' = -s x + c z: +x goes to -z";
    EXPECT_EQ(t.colour[0].at(3, 3)[3], 255);
    EXPECT_EQ(t.colour[0].at(4, 4)[3], 0) << "nothing on the +z side";
    EXPECT_EQ(t.colour[0].at(5, 2)[3], 0);
}

// Behrendt 2005 §4 on the shells: a slab's transfer is that of the surface seen from above, in
// world space. A leaf facing up with the same transfer at every vertex, turned a quarter about y,
// lands in slab 2 with its coefficients turned by lighting/transfer_rotation.h's closed form
// (c = 0, s = 1): front t2 = 0.5, t4 = 0.2 give w2 = c·t2 − s·t3 = 0, w3 = s·t2 + c·t3 = 0.5,
// w4 = c·t4 + s·t5 = 0, w5 = −s·t4 + c·t5 = −0.2; back t8 = 0.05 gives w6 = (√3/2)·s²·t8 = 0.0433,
// w7 = −c·s·t8 = 0, w8 = (1 − s²/2)·t8 = 0.025. At 4 transfer texels a side over 8 colour texels,
// the leaf's colour texels 2..5 are transfer texels 1..2, wholly covered; texels 0 and 3 take the
// slab's covered mean (the same transfer) with coverage 0, and the empty slabs zero transfer;
// Luft 2007's k_a, 1 for unit normals, rides along.
TEST(shell_bake, a_slab_carries_the_world_space_transfer_of_the_surface_seen_from_above) {
    mesh_data model;
    add_leaf(model, -1.0f, 1.0f, -1.0f, 1.0f, 2.5f);
    sh9 front{}, back{};
    front[0] = 0.8f;
    front[1] = 0.1f;
    front[2] = 0.5f;
    front[4] = 0.2f;
    back[0] = 0.3f;
    back[1] = -0.1f;
    back[8] = 0.05f;
    model.transfer.assign(model.vertices.size(), pack_transfer(front, back));
    const image_rgba8 green = solid(0, 200, 0);
    const image_rgba8 bark = solid(90, 60, 30);
    const shell_species species[] = {{&model, &green, &bark}};
    shell_plant plant;
    plant.where.xz = {2.0, 2.0};
    plant.where.yaw = 1.5707963f;
    shell_bake_settings settings = exact(8, 4, 4.0f);
    settings.transfer_texels = 4;
    const shell_stack stack = bake_shell_stack(species, std::span(&plant, 1), 4.0, settings);
    ASSERT_EQ(stack.transfer.size(), 4u * k_transfer_pages);
    const float seen[9] = {0.8f, 0.1f, 0.0f, 0.5f, 0.0f, -0.2f, 0.0f, 0.0f, 0.0f};
    const float other[9] = {0.3f, -0.1f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0433f, 0.0f, 0.025f};
    const auto channel = [&](std::uint32_t slab, std::uint32_t x, std::uint32_t z, std::size_t i) {
        return stack.transfer[slab * k_transfer_pages + i / 4].at(x, z)[i % 4];
    };
    for (std::uint32_t z = 0; z < 4; ++z)
        for (std::uint32_t x = 0; x < 4; ++x) {
            const bool covered = x >= 1 && x <= 2 && z >= 1 && z <= 2;
            EXPECT_EQ(channel(2, x, z, k_shell_transfer_coverage_channel), covered ? 255 : 0) << x << " " << z;
            for (std::size_t i = 0; i < 9; ++i) {
                EXPECT_NEAR(decode_transfer(channel(2, x, z, i)), seen[i], 0.006) << "seen " << i << " at " << x << " " << z;
                EXPECT_NEAR(decode_transfer(channel(2, x, z, 9 + i)), other[i], 0.006) << "other " << i;
                EXPECT_EQ(channel(0, x, z, i), encode_transfer(0.0f)) << "an empty slab";
            }
            EXPECT_EQ(channel(0, x, z, k_shell_transfer_coverage_channel), 0);
            EXPECT_EQ(channel(2, x, z, k_shell_transfer_ambient_channel), 255) << "k_a 1: unit normals";
            EXPECT_EQ(channel(0, x, z, k_shell_transfer_ambient_channel), 255) << "nothing to darken";
        }
    // Luft 2007's k_a rides in the normal's length (lighting "sh_implicit"): normals of length 0.6
    // give k_a 0.6, byte 0.6 * 255 = 153, where the leaf is and (the slab's mean) where it is not.
    mesh_data implicit = model;
    for (vertex& v : implicit.vertices) v.normal *= 0.6f;
    const shell_species darkened[] = {{&implicit, &green, &bark}};
    const shell_stack dark = bake_shell_stack(darkened, std::span(&plant, 1), 4.0, settings);
    for (const auto& [x, z] : {std::pair{1u, 1u}, {2u, 2u}, {0u, 3u}})
        EXPECT_EQ(dark.transfer[2 * k_transfer_pages + k_shell_transfer_ambient_channel / 4].at(x, z)[k_shell_transfer_ambient_channel % 4], 153)
            << x << " " << z;
    // Transfer asked of a species without it is refused.
    mesh_data bare;
    add_leaf(bare, -1.0f, 1.0f, -1.0f, 1.0f, 2.5f);
    const shell_species without[] = {{&bare, &green, &bark}};
    EXPECT_THROW(bake_shell_stack(without, std::span(&plant, 1), 4.0, settings), std::invalid_argument);
    settings.transfer_texels = 9;
    EXPECT_THROW(bake_shell_stack(species, std::span(&plant, 1), 4.0, settings), std::invalid_argument);
}

// A generated shrub: its slabs hold its parts from the ground up, the blur spreads coverage
// without adding any, and the bake is deterministic.
TEST(shell_bake, a_generated_plant_fills_its_slabs_and_bakes_the_same_twice) {
    const plant_model plant = generate_plant_model("shrub", 2, 64);
    const shell_species species[] = {{&plant.lods[1], &plant.leaf_texture, &plant.bark_texture}};
    shell_plant p;
    p.where.xz = {4.0, 4.0};
    shell_bake_settings settings;
    settings.texels = 32;
    settings.slices = 6;
    const shell_stack a = bake_shell_stack(species, std::span(&p, 1), 8.0, settings);
    const shell_stack b = bake_shell_stack(species, std::span(&p, 1), 8.0, settings);
    std::uint32_t filled = 0;
    for (std::size_t k = 0; k < a.colour.size(); ++k) {
        EXPECT_EQ(a.colour[k].texels, b.colour[k].texels);
        double coverage = 0.0;
        for (std::size_t i = 3; i < a.colour[k].texels.size(); i += 4) {
            coverage += a.colour[k].texels[i];
            for (std::size_t c = 1; c <= 3; ++c) EXPECT_LE(a.colour[k].texels[i - c], a.colour[k].texels[i]) << "premultiplied";
        }
        filled += coverage > 0.0 ? 1u : 0u;
    }
    EXPECT_GE(filled, 4u);
    EXPECT_EQ(a.colour[0].at(0, 0)[3], 0) << "the tile's corner is far from the shrub";
}

}  // namespace
}  // namespace sylva
