// What the command-line tests share: running the `upf` program and a scratch directory per test
// with a small dam break scene to start from.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace upf::cli_test {

namespace fs = std::filesystem;

struct Result {
  int code;
  std::string output;
};

// Runs `command` through the shell, its stderr with its stdout.
inline Result run_shell(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), int(buffer.size()), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// Runs `upf ARGS` through the shell; `env` ("NAME=value ...") goes in front of the command.
inline Result run_upf(const std::string& args, const std::string& env = "") {
  return run_shell(env + " " + std::string(UPF_EXECUTABLE) + " " + args);
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("upf_cli_" + std::string(info->test_suite_name()) + "_" + std::string(info->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  nlohmann::json sample() const {
    std::ifstream in(fs::path(UPF_SOURCE_DIR) / "samples" / "dam_break.json");
    auto doc = nlohmann::json::parse(in);
    doc["particle_spacing"] = 0.05;
    return doc;
  }
  std::string write(const nlohmann::json& doc, const std::string& name = "scene.json") const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << doc.dump(2);
    return path.string();
  }
  // Validates `doc`; expects exit code 2 and every `needle` in the message.
  void expect_rejected(const nlohmann::json& doc, std::initializer_list<std::string> needles) {
    const Result r = run_upf("validate " + write(doc));
    EXPECT_EQ(r.code, 2) << r.output;
    for (const auto& n : needles)
      EXPECT_NE(r.output.find(n), std::string::npos) << n << "\n" << r.output;
  }

  fs::path dir_;
};

}  // namespace upf::cli_test
