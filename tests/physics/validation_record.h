// One row of docs/validation.md: what a physics test measured against its reference, and the
// bound it holds it to. record_validation prints the row as a tagged JSON line into the test's
// output; scripts/update-validation-doc collects the rows of the last `make test` (ctest keeps
// every test's output in build/release/Testing/Temporary/LastTest.log) into the table, with each
// test's pass or failure, so the document quotes what the tests measured, not what someone wrote.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace upf::testing {

// `quantity`: what was measured ("floor layer pressure / rho0 g d"); `reference`: the paper,
// formula or experiment it is compared with; `expected`: the reference value as text ("1",
// "28.13 N", "0.395 s"); `bound`: the test's tolerance as text ("within 5 %"); `measured`: the
// number; `unit`: its unit ("" for a ratio).
inline void record_validation(const std::string& quantity, const std::string& reference,
                              const std::string& expected, const std::string& bound,
                              double measured, const std::string& unit = "") {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const nlohmann::json row = {
      {"test", test ? std::string(test->test_suite_name()) + "." + test->name() : ""},
      {"quantity", quantity},
      {"reference", reference},
      {"expected", expected},
      {"bound", bound},
      {"measured", measured},
      {"unit", unit}};
  std::printf("[validation] %s\n", row.dump().c_str());
  std::fflush(stdout);
}

}  // namespace upf::testing
