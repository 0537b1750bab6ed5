#pragma once
// RAII for PROJ (Debian libproj-dev): one context per use (contexts are not shared between
// threads; opening the database costs about a millisecond), and objects freed with it. Header
// only: the modules that include it link PROJ::proj themselves (io/las, registration/network).
#include <proj.h>

#include <memory>

namespace plumb {

struct ProjContext {
  PJ_CONTEXT* ctx = proj_context_create();
  ProjContext() { proj_log_level(ctx, PJ_LOG_NONE); }
  ~ProjContext() { proj_context_destroy(ctx); }
  ProjContext(const ProjContext&) = delete;
  ProjContext& operator=(const ProjContext&) = delete;
};

using ProjObject = std::unique_ptr<PJ, decltype(&proj_destroy)>;

}  // namespace plumb
