// OpenImageIO in memory: IOMemReader for decoding, IOVecOutput for encoding (OIIO >= 2.3).
#include "models/gltf/gltf_image_codec.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <string>

#include "io/input_file.h"

namespace sylva {
namespace {

namespace oiio = OIIO;

// OpenImageIO picks the format reader from the file name, so name the bytes by their magic.
std::string name_for_magic(std::span<const std::uint8_t> bytes) {
    if (bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' &&
        bytes[3] == 'G')
        return "texture.png";
    if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF)
        return "texture.jpg";
    return {};
}

}  // namespace

image_rgba8 decode_image(std::span<const std::uint8_t> bytes, std::string_view what) {
    const std::string name = name_for_magic(bytes);
    if (name.empty()) throw std::runtime_error(std::string(what) + ": not a PNG or JPEG image");
    oiio::Filesystem::IOMemReader reader(const_cast<std::uint8_t*>(bytes.data()), bytes.size());
    oiio::Filesystem::IOProxy* proxy = &reader;
    oiio::ImageSpec config;
    config.attribute("oiio:ioproxy", oiio::TypeDesc::PTR, &proxy);
    config.attribute("oiio:UnassociatedAlpha", 1);  // glTF colours are straight, not premultiplied
    auto input = oiio::ImageInput::open(name, &config);
    if (!input) throw std::runtime_error(std::string(what) + ": " + oiio::geterror());
    const oiio::ImageSpec& spec = input->spec();
    // The header's size is bounded before a pixel buffer is allocated for it: a 100-byte PNG can
    // claim 30000 x 30000 pixels.
    check_image_dimensions(std::string(what), spec.width, spec.height);
    const int channels = spec.nchannels;
    std::vector<std::uint8_t> raw(std::size_t(spec.width) * std::size_t(spec.height) *
                                  std::size_t(channels));
    if (channels < 1 || !input->read_image(0, 0, 0, channels, oiio::TypeDesc::UINT8, raw.data()))
        throw std::runtime_error(std::string(what) + ": " + input->geterror());
    image_rgba8 out;
    out.width = std::uint32_t(spec.width);
    out.height = std::uint32_t(spec.height);
    out.texels.resize(std::size_t(out.width) * out.height * 4);
    for (std::size_t i = 0, n = std::size_t(out.width) * out.height; i < n; ++i) {
        const std::uint8_t* s = &raw[i * std::size_t(channels)];
        std::uint8_t* d = &out.texels[i * 4];
        const bool grey = channels < 3;
        d[0] = s[0];
        d[1] = grey ? s[0] : s[1];
        d[2] = grey ? s[0] : s[2];
        d[3] = channels == 2 ? s[1] : channels >= 4 ? s[3] : 255;
    }
    return out;
}

std::vector<std::uint8_t> encode_png(const image_rgba8& image) {
    std::vector<unsigned char> bytes;
    oiio::Filesystem::IOVecOutput writer(bytes);
    oiio::Filesystem::IOProxy* proxy = &writer;
    oiio::ImageSpec spec(int(image.width), int(image.height), 4, oiio::TypeDesc::UINT8);
    spec.attribute("oiio:ioproxy", oiio::TypeDesc::PTR, &proxy);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    auto output = oiio::ImageOutput::create("texture.png");
    if (!output || !output->open("texture.png", spec) ||
        !output->write_image(oiio::TypeDesc::UINT8, image.texels.data()) || !output->close())
        throw std::runtime_error("cannot encode a PNG: " +
                                 (output ? output->geterror() : oiio::geterror()));
    return {bytes.begin(), bytes.end()};
}

image_rgba8 resize_image(const image_rgba8& image, std::uint32_t width, std::uint32_t height) {
    if (image.width == width && image.height == height) return image;
    const oiio::ImageSpec source_spec(int(image.width), int(image.height), 4,
                                      oiio::TypeDesc::UINT8);
    const oiio::ImageBuf source(source_spec, const_cast<std::uint8_t*>(image.texels.data()));
    oiio::ImageBuf resized(oiio::ImageSpec(int(width), int(height), 4, oiio::TypeDesc::UINT8));
    if (!oiio::ImageBufAlgo::resize(resized, source))
        throw std::runtime_error("cannot resize a texture: " + resized.geterror());
    image_rgba8 out;
    out.width = width;
    out.height = height;
    out.texels.resize(std::size_t(width) * height * 4);
    resized.get_pixels(oiio::ROI::All(), oiio::TypeDesc::UINT8, out.texels.data());
    return out;
}

}  // namespace sylva
