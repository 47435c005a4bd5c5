#include "models/bake/transfer_pages.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/cache/mesh_io.h"

namespace sylva {

std::uint8_t encode_transfer(float t) {
    const float unit = std::clamp(t / k_transfer_page_range * 0.5f + 0.5f, 0.0f, 1.0f);
    return std::uint8_t(std::lround(unit * 255.0f));
}

float decode_transfer(std::uint8_t byte) {
    return (float(byte) / 255.0f * 2.0f - 1.0f) * k_transfer_page_range;
}

std::vector<image_rgba8> blank_transfer_pages(std::uint32_t width, std::uint32_t height) {
    std::vector<image_rgba8> pages(k_transfer_pages);
    for (image_rgba8& page : pages) {
        page.width = width;
        page.height = height;
        page.texels.assign(std::size_t(width) * height * 4, encode_transfer(0.0f));
    }
    return pages;
}

void blit_transfer(std::vector<image_rgba8>& pages, const billboard_image& image, std::uint32_t x0,
                   std::uint32_t y0) {
    const std::uint32_t w = image.albedo.width, h = image.albedo.height;
    if (pages.size() != k_transfer_pages ||
        image.transfer.size() != std::size_t(w) * h * k_billboard_transfer_floats)
        throw std::invalid_argument(
            "blit_transfer: pages or the image's transfer have the wrong size");
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const float* t =
                &image.transfer[(std::size_t(y) * w + x) * k_billboard_transfer_floats];
            for (std::size_t i = 0; i < std::size_t(k_transfer_pages) * 4; ++i) {
                const float value = i < k_billboard_transfer_floats ? t[i] : 0.0f;
                pages[i / 4].at(x0 + x, y0 + y)[i % 4] = encode_transfer(value);
            }
        }
}

void write_transfer_pages(binary_writer& out, const std::vector<image_rgba8>& pages) {
    out.pod(std::uint32_t(pages.size()));
    for (const image_rgba8& page : pages) write_image(out, page);
}

std::vector<image_rgba8> read_transfer_pages(binary_reader& in, std::uint32_t width, std::uint32_t height,
                                             const std::string& owner) {
    const auto count = in.pod<std::uint32_t>();
    if (count != 0 && count != k_transfer_pages)
        throw std::runtime_error("bake cache entry: " + owner + " has " + std::to_string(count) + " transfer pages");
    std::vector<image_rgba8> pages(count);
    for (image_rgba8& page : pages) {
        page = read_image(in);
        if (page.width != width || page.height != height)
            throw std::runtime_error("bake cache entry: " + owner + " transfer pages differ in size from its atlas");
    }
    return pages;
}

}  // namespace sylva
