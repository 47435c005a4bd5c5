#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <span>
#include <stdexcept>
#include <string>

#include "io/atomic_file.h"
#include "models/generate/textures.h"

namespace sylva {

// OpenImageIO's file writers do not all report a short write on a full disk, so the image is
// encoded in memory (its ioproxy) and written by write_atomically, which checks every write
// and the close: a frame is either complete on disk or an error naming it.
void write_image(const image_rgba8& image, const std::filesystem::path& path) {
    const std::string name = path.string();
    if (image.width == 0 || image.height == 0 || image.texels.size() != std::size_t(image.width) * image.height * 4)
        throw std::runtime_error("write_image: " + name + ": image is empty or its texel count is wrong");
    auto out = OIIO::ImageOutput::create(name);
    if (!out) throw std::runtime_error("write_image: " + name + ": no writer (" + OIIO::geterror() + ")");
    if (!out->supports("ioproxy"))
        throw std::runtime_error("write_image: " + name + ": the " + out->format_name() +
                                 " writer cannot encode in memory");
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 4, OIIO::TypeDesc::UINT8);
    // Our texels are unassociated (straight) alpha; without this OpenImageIO premultiplies on
    // the way to PNG and changes the colour of semi-transparent texels.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->set_ioproxy(&memory) || !out->open(name, spec))
        throw std::runtime_error("write_image: cannot encode " + name + ": " + out->geterror());
    const bool written = out->write_image(OIIO::TypeDesc::UINT8, image.texels.data());
    const std::string error = written ? std::string() : out->geterror();
    if (!out->close() || !written) throw std::runtime_error("write_image: cannot encode " + name + ": " + error);
    write_atomically(path, std::as_bytes(std::span(bytes.data(), bytes.size())));
}

}  // namespace sylva
