// Bad surface tension input (docs/surface-tension.md) is refused before anything runs: exit code
// 2, the JSON path, and the allowed range or names.
#include "tests/cli/cli_support.h"

namespace {

using namespace upf::cli_test;

TEST_F(Cli, NegativeSurfaceTensionNamesItsRange) {
  auto doc = sample();
  doc["materials"]["water"]["surface_tension"] = -0.07;
  expect_rejected(doc, {"/materials/water/surface_tension", "out of range", "[0, 10]"});
}

TEST_F(Cli, UnregisteredSurfaceTensionModelIsNamedWithTheRegisteredOnes) {
  auto doc = sample();
  doc["materials"]["water"]["surface_tension"] = 0.07;
  doc["materials"]["water"]["surface_tension_model"] = "akinci2031";
  expect_rejected(
      doc, {"/materials/water/surface_tension_model", "no surface tension model named 'akinci2031'",
            "did you mean 'akinci2013'"});
}

TEST_F(Cli, AdhesionMustNameABoundaryMaterialWithinRange) {
  auto doc = sample();
  doc["materials"]["water"]["surface_tension"] = 0.07;
  doc["materials"]["water"]["adhesion"] = {{"wals", 1.0}};
  expect_rejected(
      doc, {"/materials/water/adhesion/wals", "no material named 'wals'", "did you mean 'walls'"});
  doc["materials"]["water"]["adhesion"] = {{"water", 1.0}};
  expect_rejected(doc, {"/materials/water/adhesion/water", "is a liquid material"});
  doc["materials"]["water"]["adhesion"] = {{"walls", -1.0}};
  expect_rejected(doc, {"/materials/water/adhesion/walls", "out of range"});
}

// A contact angle beyond the adhesion's reach, one given beside a ratio for the same material, a
// name that is not a boundary: each named with its JSON path (adhesion_contact_angle.h).
TEST_F(Cli, ContactAngleMustBeReachableAndNotBesideARatio) {
  auto doc = sample();
  doc["materials"]["water"]["surface_tension"] = 0.07;
  doc["materials"]["water"]["contact_angle"] = {{"walls", 60}};
  expect_rejected(doc, {"/materials/water/contact_angle/walls", "60 degrees",
                        "from 85 to 180 degrees", "wets completely"});
  doc["materials"]["water"]["contact_angle"] = {{"walls", 200}};
  expect_rejected(doc, {"/materials/water/contact_angle/walls", "out of range"});
  doc["materials"]["water"]["contact_angle"] = {{"walls", 120}};
  doc["materials"]["water"]["adhesion"] = {{"walls", 4}};
  expect_rejected(doc, {"/materials/water/contact_angle/walls", "has an adhesion ratio too"});
  doc["materials"]["water"].erase("adhesion");
  doc["materials"]["water"]["contact_angle"] = {{"wals", 120}};
  expect_rejected(doc, {"/materials/water/contact_angle/wals", "did you mean 'walls'"});
  doc["materials"]["water"]["contact_angle"] = {{"walls", 120}};
  EXPECT_EQ(run_upf("validate " + write(doc)).code, 0);
}

// The continuum surface force has no cohesion to balance Akinci's adhesion: asking it for wetting,
// by ratio or by angle, is refused with the model's name and the one that wets.
TEST_F(Cli, WettingWithAModelWithoutAdhesionIsRefused) {
  auto doc = sample();
  doc["materials"]["water"]["surface_tension"] = 0.07;
  doc["materials"]["water"]["surface_tension_model"] = "csf";
  doc["materials"]["water"]["adhesion"] = {{"walls", 1.0}};
  expect_rejected(doc, {"/materials/water/adhesion", "'csf' has no adhesion", "'akinci2013'"});
  doc["materials"]["water"].erase("adhesion");
  doc["materials"]["water"]["contact_angle"] = {{"walls", 120}};
  expect_rejected(doc, {"/materials/water/contact_angle", "'csf' has no adhesion"});
  doc["materials"]["water"].erase("contact_angle");
  EXPECT_EQ(run_upf("validate " + write(doc)).code, 0);
}

TEST_F(Cli, AdhesionWithoutSurfaceTensionSaysWhatToSet) {
  auto doc = sample();
  doc["materials"]["water"]["adhesion"] = {{"walls", 1.0}};
  expect_rejected(doc, {"/materials/water/adhesion", "surface_tension is 0",
                        "/materials/water/surface_tension"});
}

TEST_F(Cli, InfoListsTheSurfaceTensionModels) {
  const Result r = run_upf("info");
  EXPECT_EQ(r.code, 0);
  for (const char* s :
       {"Surface tension models", "akinci2013 (the default)", "Akinci", "surface_tension", "N/m"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s;
}

}  // namespace
