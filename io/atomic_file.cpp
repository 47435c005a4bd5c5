#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include "io/file_kind.h"

namespace sylva {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
    throw output_error("cannot write " + path.string() + ": " + reason);
}

// Unique within the process (threads) and across processes (pid), so two writers of one target
// never share a temporary file; hidden, so a half-written one is not mistaken for output.
std::filesystem::path temporary_name(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    std::string name(1, '.');  // appended piece by piece: GCC 12 warns (-Wrestrict) on "." + ...
    name += path.filename().string();
    name += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    return path.parent_path() / name;
}

// POSIX write(2) rather than an ofstream: every short write and error is seen, with its errno.
bool write_all(int fd, const std::byte* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

}  // namespace

void write_atomically(const std::filesystem::path& path, std::string_view content) {
    write_atomically(path, std::as_bytes(std::span(content.data(), content.size())));
}

void write_atomically(const std::filesystem::path& path, std::span<const std::byte> content) {
    if (path.empty() || !path.has_filename()) fail(path, "not a file name");
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode))
        fail(path, "it is " + file_kind_name(existing.st_mode) + ", not a regular file");
    const std::filesystem::path temporary = temporary_name(path);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(path, std::strerror(errno));
    const bool written = write_all(fd, content.data(), content.size());
    const int write_errno = errno;
    // close() reports errors some file systems (NFS, quotas) only find at the end.
    const bool closed = ::close(fd) == 0;
    const int close_errno = errno;
    if (!written || !closed) {
        ::unlink(temporary.c_str());
        fail(path, std::strerror(written ? close_errno : write_errno));
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const int rename_errno = errno;
        ::unlink(temporary.c_str());
        fail(path, std::strerror(rename_errno));
    }
}

}  // namespace sylva
