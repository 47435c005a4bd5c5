#include "app/process_memory.h"

#include <fstream>
#include <string>

namespace sylva {

double peak_resident_mb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
    return 0.0;
}

void reset_peak_resident() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
}

}  // namespace sylva
