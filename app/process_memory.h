#pragma once
// The process's resident-memory high-water mark, read from Linux's /proc, so the bench can
// report each configuration's own peak.
namespace sylva {

// VmHWM in MB (0 where /proc/self/status has none).
double peak_resident_mb();
// Resets VmHWM to the current resident size (writing 5 to /proc/self/clear_refs, Linux 4.0+);
// does nothing elsewhere.
void reset_peak_resident();

}  // namespace sylva
