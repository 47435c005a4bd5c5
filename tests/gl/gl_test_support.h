#pragma once
// A shared OSMesa context for GL tests. Tests that need GL call SYLVA_REQUIRE_GL() first, which
// makes it current; without a context they are skipped (GTEST_SKIP) with the reason, never
// failed or silently passed.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "systems/render/gl_context.h"

namespace sylva::testing {

inline render::gl_context* shared_gl_context(std::string* reason = nullptr) {
    static std::unique_ptr<render::gl_context> context;
    static std::string failure;
    static bool tried = false;
    if (!tried) {
        tried = true;
        try {
            render::context_options options;
            options.width = 64;
            options.height = 64;
            options.headless = true;
            context = render::create_context(options);
        } catch (const std::exception& e) {
            failure = e.what();
        }
    }
    if (reason) *reason = failure;
    return context.get();
}

// The shared context, made current: a test that made a context of its own leaves none current
// when that one is destroyed, and GL calls without a current context do nothing and report no
// error (a map then returns null).
inline render::gl_context* current_shared_gl_context(std::string* reason = nullptr) {
    render::gl_context* context = shared_gl_context(reason);
    if (context) context->make_current();
    return context;
}

}  // namespace sylva::testing

#define SYLVA_REQUIRE_GL()                                                     \
    do {                                                                       \
        std::string sylva_gl_reason;                                           \
        if (!::sylva::testing::current_shared_gl_context(&sylva_gl_reason))    \
            GTEST_SKIP() << "no GL 4.5 context (OSMesa): " << sylva_gl_reason; \
    } while (0)
