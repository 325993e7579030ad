// The lighting key's one writer against keys worked out by hand from its bit table (key.h).
#include <gtest/gtest.h>

#include "lighting/lighting.h"

namespace ffc::lighting {
namespace {

TEST(Key, NothingEnabledIsAlmostEmpty) {
  LightParams l[8];
  MaterialParams m[2];
  const Key k = make_key(l, m, ModelParams{}, false, false);
  EXPECT_EQ(k.bits, 0u);
  EXPECT_EQ(k.extra, 1u << 9);  // GL's default shininess is 0
  EXPECT_FALSE(k.any_light());
}

TEST(Key, EachTermInItsBit) {
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  l[0].enabled = true;  // directional, no spot: only bit 0
  l[2].enabled = true, l[2].position = {1, 2, 3, 1}, l[2].spot_cutoff = 45, l[2].linear_attenuation = 0.5;
  l[5].enabled = true, l[5].position = {0, 0, 0, 2};  // local, not attenuated
  l[6].spot_cutoff = 10;                              // off: no bits at all
  l[5].specular = {0, 0.5, 0, 1};
  m[1].specular = {0, 1, 0, 1};  // the back face's product makes the specular term exist
  m[0].shininess = 12;
  model.two_side = model.separate_specular = true;
  const Key k = make_key(l, m, model, true, false);
  EXPECT_EQ(k.bits, (1u << 0 | 1u << 2 | 1u << 5) | (1u << 10 | 1u << 13) | (1u << 18) | (1u << 24 | 1u << 26 | 1u << 28));
  EXPECT_EQ(k.extra, 1u << 2 | 1u << 8);
  EXPECT_TRUE(k.attenuated(2));
  EXPECT_FALSE(k.attenuated(5));
  EXPECT_TRUE(k.specular());
  EXPECT_FALSE(k.shininess_zero());
}

TEST(Key, TrackedSpecularColourBringsTheTerm) {
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  l[0].enabled = true, l[0].specular = {1, 1, 1, 1};  // material specular is 0: no term
  EXPECT_FALSE(make_key(l, m, model, false, false).specular());
  model.color_material = true, model.cm_mode = 0x1202;  // GL_SPECULAR
  const Key k = make_key(l, m, model, false, true);
  EXPECT_TRUE(k.specular());
  EXPECT_TRUE(k.color_material());
  EXPECT_TRUE(k.rescale());
  model.cm_mode = 0x1201;  // GL_DIFFUSE
  EXPECT_FALSE(make_key(l, m, model, false, false).specular());
}

TEST(Key, SettersClearAsWellAsSet) {
  Key k;
  k.set_light(3, true, true, true);
  k.set_light(3, false, true, false);
  EXPECT_EQ(k.bits, 1u << 3 | 1u << 19);
  EXPECT_EQ(k.extra, 0u);
  k.set(Key::kLocalViewer);
  k.set(Key::kLocalViewer, false);
  EXPECT_EQ(k.bits, 1u << 3 | 1u << 19);
}

}  // namespace
}  // namespace ffc::lighting
