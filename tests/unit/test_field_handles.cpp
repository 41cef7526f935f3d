// Typed field handles (framework/particles/field_handle.h): a solver declares its fields in
// prepare() and reaches them through handles; once the world is prepared, a name nobody declared
// is an error that names the field (and the reader), never a silently created zero field.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "framework/particles/particles.h"

namespace upf {
namespace {

std::string logic_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST(FieldHandles, ADeclaredHandleReachesItsArrayAndFollowsAdd) {
  Particles p;
  p.add({0, 0, 0}, {}, 1, ParticleType::Liquid, 0);
  const FieldHandle<Real> pressure = p.declare_scalar("test.pressure", Real(2.5), true);
  const FieldHandle<Vec3> force = p.declare_vector("test.force", Vec3{1, 2, 3});
  p.add({1, 0, 0}, {}, 1, ParticleType::Liquid, 0);
  ASSERT_EQ(p[pressure].size(), 2u);
  EXPECT_EQ(p[pressure][0], Real(2.5));
  EXPECT_EQ(&p[pressure], &p.scalar_field("test.pressure"));
  EXPECT_EQ(p[force][0].y, Real(2));
  EXPECT_TRUE(p.scalar_fields().at("test.pressure").exported);
  // Declaring again finds the same field.
  EXPECT_EQ(&p[p.declare_scalar("test.pressure")], &p[pressure]);
}

TEST(FieldHandles, AfterSealingAnUndeclaredNameIsAnErrorNamingIt) {
  Particles p;
  p.add({0, 0, 0}, {}, 1, ParticleType::Liquid, 0);
  p.declare_scalar("density");
  p.seal_fields();
  EXPECT_NO_THROW(p.scalar_field("density"));
  const std::string m = logic_error_of([&] { p.scalar_field("densty"); });
  EXPECT_NE(m.find("'densty'"), std::string::npos) << m;
  EXPECT_EQ(p.find_scalar("densty"), nullptr) << "the misspelt name must not create a field";
}

TEST(FieldHandles, ReadingAFieldNobodyDeclaredNamesTheReaderAndTheFieldsThereAre) {
  Particles p;
  p.declare_scalar("radius");
  const std::string m = logic_error_of([&] { p.scalar("radiuss", "dem_linear"); });
  EXPECT_NE(m.find("'dem_linear'"), std::string::npos) << m;
  EXPECT_NE(m.find("'radiuss'"), std::string::npos) << m;
  EXPECT_NE(m.find("radius"), std::string::npos) << m;
  EXPECT_NO_THROW(p.scalar("radius", "dem_linear"));
}

TEST(FieldHandles, AHandleOfOtherParticlesOrNoneIsRefused) {
  Particles a, b;
  const FieldHandle<Real> h = a.declare_scalar("x");
  b.declare_scalar("x");
  EXPECT_THROW(b[h], std::logic_error);
  EXPECT_THROW(a[FieldHandle<Real>{}], std::logic_error);
}

}  // namespace
}  // namespace upf
