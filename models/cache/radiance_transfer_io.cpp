#include "models/cache/radiance_transfer_io.h"

#include <stdexcept>
#include <string>

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x54525953;  // "SYRT"

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("bake cache entry: radiance transfer " + what);
}

}  // namespace

void write_radiance_transfer(binary_writer& out, const radiance_transfer& transfer) {
    out.pod(transfer.bands);
    out.array(transfer.front);
    out.array(transfer.back);
}

radiance_transfer read_radiance_transfer(binary_reader& in) {
    radiance_transfer t;
    t.bands = in.pod<std::uint32_t>();
    if (t.bands != 2 && t.bands != 3)
        fail("has " + std::to_string(t.bands) + " bands (2 or 3 expected)");
    t.front = in.array<float>();
    t.back = in.array<float>();
    if (t.front.size() != t.back.size()) fail("front and back sizes differ");
    if (t.front.size() % (t.bands * t.bands) != 0) fail("size is not a multiple of bands^2");
    return t;
}

std::vector<std::byte> serialize_radiance_transfers(std::span<const radiance_transfer> transfers) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_radiance_transfer_format);
    out.pod(std::uint32_t(transfers.size()));
    for (const radiance_transfer& t : transfers) write_radiance_transfer(out, t);
    return std::move(out.bytes());
}

std::vector<radiance_transfer> deserialize_radiance_transfers(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) fail("has the wrong magic number");
    if (const auto format = in.pod<std::uint32_t>(); format != k_radiance_transfer_format)
        fail("has format " + std::to_string(format) + ", expected " +
             std::to_string(k_radiance_transfer_format));
    const auto count = in.pod<std::uint32_t>();
    std::vector<radiance_transfer> transfers;
    for (std::uint32_t i = 0; i < count; ++i) transfers.push_back(read_radiance_transfer(in));
    if (!in.at_end()) fail("has trailing bytes");
    return transfers;
}

}  // namespace sylva
