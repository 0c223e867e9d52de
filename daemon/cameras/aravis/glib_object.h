// GObjectPtr: a GObject reference owned by a unique_ptr, released with g_object_unref; and
// GErrorSlot for the GError a call may set. Private to the Aravis backend (it includes glib).
#pragma once

#include <memory>
#include <string>

#include <glib-object.h>

namespace vem::cameras {

struct GObjectUnref {
  void operator()(void* object) const {
    if (object != nullptr) g_object_unref(object);
  }
};

template <typename T>
using GObjectPtr = std::unique_ptr<T, GObjectUnref>;

// Collects a GError from a glib call: `call(..., error.out())`, then `if (error) ...`. Frees it.
class GErrorSlot {
 public:
  GErrorSlot() = default;
  GErrorSlot(const GErrorSlot&) = delete;
  GErrorSlot& operator=(const GErrorSlot&) = delete;
  ~GErrorSlot() { clear(); }

  [[nodiscard]] GError** out() {
    clear();
    return &error_;
  }
  explicit operator bool() const { return error_ != nullptr; }
  [[nodiscard]] std::string message() const { return error_ != nullptr ? error_->message : ""; }
  void clear() {
    if (error_ != nullptr) g_error_free(error_);
    error_ = nullptr;
  }

 private:
  GError* error_ = nullptr;
};

}  // namespace vem::cameras
