#include "io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/file_kind.h"

namespace sylva {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
    throw input_error(path.string() + ": " + problem);
}

std::string megabytes(std::uint64_t bytes) {
    return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MB";
}

// Owns a descriptor opened for reading. O_NONBLOCK: opening a FIFO with no writer returns at
// once instead of hanging (it is then refused as not a regular file); it changes nothing for
// regular files. fstat on the open descriptor checks the very file that will be read.
class input_descriptor {
public:
    input_descriptor(const std::filesystem::path& path, std::uint64_t max_bytes) {
        m_fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
        if (m_fd < 0) fail(path, std::string("cannot open file: ") + std::strerror(errno));
        struct stat info {};
        if (::fstat(m_fd, &info) != 0) fail(path, std::string("cannot read file: ") + std::strerror(errno));
        if (!S_ISREG(info.st_mode))
            fail(path, "is " + file_kind_name(info.st_mode) + ", not a regular file");
        m_size = std::uint64_t(info.st_size);
        if (m_size > max_bytes)
            fail(path, "is " + megabytes(m_size) + ", more than the " + megabytes(max_bytes) + " limit");
    }
    ~input_descriptor() {
        if (m_fd >= 0) ::close(m_fd);
    }
    input_descriptor(const input_descriptor&) = delete;
    input_descriptor& operator=(const input_descriptor&) = delete;

    int fd() const { return m_fd; }
    std::uint64_t size() const { return m_size; }

private:
    int m_fd = -1;
    std::uint64_t m_size = 0;
};

}  // namespace

std::uint64_t check_input_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
    return input_descriptor(path, max_bytes).size();
}

std::string read_input_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
    const input_descriptor in(path, max_bytes);
    std::string text(std::size_t(in.size()), '\0');
    std::size_t done = 0;
    while (true) {
        if (done == text.size()) {
            if (done >= max_bytes) {  // only a file that grew gets here: one byte more is too many
                char extra = 0;
                if (::read(in.fd(), &extra, 1) > 0)
                    fail(path, "is more than the " + megabytes(max_bytes) + " limit");
                break;
            }
            text.resize(std::min<std::uint64_t>(max_bytes, done + (1u << 16)));  // it grew
        }
        const ssize_t n = ::read(in.fd(), text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail(path, std::string("cannot read file: ") + std::strerror(errno));
        if (n == 0) break;
        done += std::size_t(n);
    }
    text.resize(done);
    return text;
}

void check_image_dimensions(const std::string& what, long long width, long long height) {
    const auto size_text = std::to_string(width) + "x" + std::to_string(height) + " pixels";
    if (width < 1 || height < 1) throw input_error(what + ": " + size_text + "; an image needs at least one pixel");
    if (std::uint64_t(width) > k_max_image_side || std::uint64_t(height) > k_max_image_side ||
        std::uint64_t(width) * std::uint64_t(height) > k_max_image_pixels)
        throw input_error(what + ": " + size_text + " is more than Sylva reads (at most " +
                          std::to_string(k_max_image_side) + " per side and " +
                          std::to_string(k_max_image_pixels >> 20) + " M pixels)");
}

}  // namespace sylva
