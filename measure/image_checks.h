#pragma once
// Internal to measure/: argument checks shared by the metric implementations.
#include "models/image/image.h"

namespace sylva {

// Throws std::invalid_argument "<metric>: image sizes differ (WxH vs WxH)" when a and b differ
// in size, or "<metric>: ... texel count" when an image's texels do not match its size.
void require_same_size(const image_rgba8& a, const image_rgba8& b, const char* metric);

}  // namespace sylva
