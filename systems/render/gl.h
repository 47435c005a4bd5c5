#pragma once
// The one include for GL in Sylva: the glad-generated GL 4.5 core loader. Only files in
// render/ include this, and only the thread that owns the context calls into it.
#include <glad/gl.h>
