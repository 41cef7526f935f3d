// Shared by the test_mesh_*.cpp files: where the meshes are, and catching InputError messages.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "framework/core/errors.h"

namespace upf::mesh_test {

inline std::filesystem::path asset(const std::string& name) {
  return std::filesystem::path(UPF_SOURCE_DIR) / "assets" / "meshes" / name;
}

inline std::filesystem::path test_mesh(const std::string& name) {
  return std::filesystem::path(UPF_SOURCE_DIR) / "tests" / "data" / "meshes" / name;
}

// Runs `f`, expects an InputError and returns its text ("where: message" lines); "" with a
// failure when nothing or something else was thrown.
template <class F>
std::string input_error_text(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return "";
}

}  // namespace upf::mesh_test
