#pragma once
// What a path is, in words for an error message ("a directory", "a character device").
#include <string>
#include <sys/stat.h>

namespace sylva {

std::string file_kind_name(mode_t mode);

}  // namespace sylva
