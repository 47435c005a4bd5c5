#include "app/atomic_file.h"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace sylva {

void write_atomically(const std::filesystem::path& path, const std::string& content) {
    const std::filesystem::path temporary = path.string() + ".tmp";
    std::error_code ignored;
    {
        std::ofstream out(temporary, std::ios::binary);
        out << content;
        out.close();
        if (!out) {
            std::filesystem::remove(temporary, ignored);
            throw std::runtime_error("cannot write " + path.string());
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
    }
}

}  // namespace sylva
