// Contract checks: how every library of vemcast states a precondition or an invariant.
//
//   VEM_EXPECTS(condition)   a precondition or invariant the caller (or this code) must keep
//   VEM_UNREACHABLE(what)    a branch no correct program takes (`what` says why it cannot)
//
// A broken contract is a bug, never a runtime condition (those are values: std::expected,
// std::optional). The checks stay on in every build type, Release included (unlike assert, which
// NDEBUG removes): a violation writes one line to stderr, "file:line: condition: contract
// violated", and calls std::abort(). Checks are per call, never per pixel or per sample: a loop's
// precondition is checked once before the loop (docs/conventions.md, "Contract checks").
// Header-only and dependency-free (the fuzz targets compile it as it is).
#pragma once

#include <cstdio>
#include <cstdlib>

namespace vem::util {

// Reports a broken contract and aborts; what VEM_EXPECTS and VEM_UNREACHABLE call.
[[noreturn, gnu::cold, gnu::noinline]] inline void contractViolated(const char* file, int line,
                                                                    const char* what) noexcept {
  std::fprintf(stderr, "%s:%d: %s: contract violated\n", file, line, what);
  std::fflush(stderr);
  std::abort();
}

}  // namespace vem::util

#define VEM_EXPECTS(condition)            \
  (static_cast<bool>(condition) ? void(0) \
                                : ::vem::util::contractViolated(__FILE__, __LINE__, #condition))

#define VEM_UNREACHABLE(what) ::vem::util::contractViolated(__FILE__, __LINE__, what)
