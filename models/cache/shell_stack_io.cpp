#include "models/cache/shell_stack_io.h"

#include <stdexcept>
#include <string>

#include "models/cache/bake_cache.h"
#include "models/bake/transfer_pages.h"
#include "models/cache/mesh_io.h"

namespace sylva {
namespace {
constexpr std::uint32_t k_magic = 0x4c4c4853;  // "SHLL"
}

std::vector<std::byte> serialize_shell_stacks(const std::vector<shell_stack>& stacks) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_shell_format);
    out.pod(std::uint64_t(stacks.size()));
    for (const shell_stack& s : stacks) {
        out.pod(s.tile_size_m);
        out.pod(s.slice_height_m);
        out.pod(std::uint64_t(s.colour.size()));
        for (std::size_t k = 0; k < s.colour.size(); ++k) {
            write_image(out, s.colour[k]);
            write_image(out, s.normal[k]);
        }
        out.pod(std::uint64_t(s.transfer.size()));
        for (const image_rgba8& page : s.transfer) write_image(out, page);
    }
    return std::move(out.bytes());
}

std::vector<shell_stack> deserialize_shell_stacks(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) throw std::runtime_error("not a shell texture entry");
    if (const auto format = in.pod<std::uint32_t>(); format != k_shell_format)
        throw std::runtime_error("shell texture format " + std::to_string(format) + ", expected " +
                                 std::to_string(k_shell_format));
    const auto count = in.pod<std::uint64_t>();
    if (count > 65536) throw std::runtime_error("shell textures: implausible tile count " + std::to_string(count));
    std::vector<shell_stack> stacks(count);
    for (shell_stack& s : stacks) {
        s.tile_size_m = in.pod<double>();
        s.slice_height_m = in.pod<float>();
        const auto slices = in.pod<std::uint64_t>();
        if (slices == 0 || slices > 256) throw std::runtime_error("shell textures: implausible slice count");
        for (std::uint64_t k = 0; k < slices; ++k) {
            s.colour.push_back(read_image(in));
            s.normal.push_back(read_image(in));
            const image_rgba8& first = s.colour.front();
            for (const image_rgba8* i : {&s.colour.back(), &s.normal.back()})
                if (i->width != first.width || i->height != first.height || i->width == 0)
                    throw std::runtime_error("shell textures: slices of different sizes");
        }
        if (s.colour.front().width != stacks.front().colour.front().width)
            throw std::runtime_error("shell textures: tiles of different sizes");
        const auto pages = in.pod<std::uint64_t>();
        if (pages != 0 && pages != slices * k_transfer_pages)
            throw std::runtime_error("shell textures: " + std::to_string(pages) + " transfer pages for " +
                                     std::to_string(slices) + " slices");
        for (std::uint64_t p = 0; p < pages; ++p) {
            s.transfer.push_back(read_image(in));
            const image_rgba8& first = s.transfer.front();
            if (s.transfer.back().width != first.width || s.transfer.back().height != first.height ||
                first.width == 0 || first.width > s.colour.front().width)
                throw std::runtime_error("shell textures: transfer pages of different or impossible sizes");
        }
        if (s.transfer.empty() != stacks.front().transfer.empty() ||
            (!s.transfer.empty() && s.transfer.front().width != stacks.front().transfer.front().width))
            throw std::runtime_error("shell textures: tiles with and without transfer, or of different sizes");
    }
    if (!in.at_end()) throw std::runtime_error("shell textures: trailing bytes");
    return stacks;
}

}  // namespace sylva
