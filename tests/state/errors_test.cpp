// Errors: each row makes one call (or a short sequence) with a wrong enum, an out-of-range value
// or inside glBegin/glEnd, on Mesa and on our context. The error glGetError returns must be
// Mesa's (pinned in the row), the next glGetError GL_NO_ERROR, and the state read back afterwards
// unchanged and equal to Mesa's. See harness.h for the comparison.
#include <climits>
#include <limits>

#include "harness.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR, IE = GL_INVALID_ENUM, IV = GL_INVALID_VALUE, IO = GL_INVALID_OPERATION,
                 SO = GL_STACK_OVERFLOW, SU = GL_STACK_UNDERFLOW;
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// Non-default light state, so an erroneous call that wrote anything would show.
void lit_setup() {
  light1(GL_LIGHT2, GL_SPOT_EXPONENT, 10);
  light1(GL_LIGHT2, GL_SPOT_CUTOFF, 45);
  light1(GL_LIGHT2, GL_CONSTANT_ATTENUATION, 2);
  light1(GL_LIGHT2, GL_LINEAR_ATTENUATION, 0.5f);
  light1(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, 0.25f);
  light4(GL_LIGHT2, GL_AMBIENT, 0.1f, 0.2f, 0.3f, 0.4f);
  material4(GL_FRONT_AND_BACK, GL_AMBIENT, 0.3f, 0.2f, 0.1f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 17);
  glMaterialf(GL_BACK, GL_SHININESS, 33);
}

class Errors : public ::testing::TestWithParam<Case> {};
TEST_P(Errors, MatchMesa) { check_case(GetParam()); }

// ---------------------------------------------------------------- glLight*

INSTANTIATE_TEST_SUITE_P(Light, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"Lightfv_Light8", lit_setup, [] { light4(GL_LIGHT0 + 8, GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Lightfv_LightBelowLight0", lit_setup, [] { light4(GL_LIGHT0 - 1, GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Lightfv_LightIsLighting", lit_setup, [] { light4(GL_LIGHTING, GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Lightfv_PnameEmission", lit_setup, [] { light4(GL_LIGHT2, GL_EMISSION, 1, 1, 1, 1); }, IE},
  {"Lightfv_PnameShininess", lit_setup, [] { light1(GL_LIGHT2, GL_SHININESS, 5); }, IE},
  {"Lightfv_PnameLightModelAmbient", lit_setup, [] { light4(GL_LIGHT2, GL_LIGHT_MODEL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Lightfv_BadLightAndBadPname", lit_setup, [] { light4(GL_LIGHT0 + 8, GL_EMISSION, 1, 1, 1, 1); }, IE},
  {"Lightfv_BadLightAndBadValue", lit_setup, [] { light1(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, 91); }, IE},
  {"Lightfv_SpotExponentMinus1", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, -1); }, IV},
  {"Lightfv_SpotExponent128_5", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, 128.5f); }, IV},
  {"Lightfv_SpotExponent129", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, 129); }, IV},
  {"Lightfv_SpotExponentInfinity", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, kInf); }, IV},
  {"Lightfv_SpotExponent128IsValid", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, 128); }, OK},
  {"Lightfv_SpotExponent0IsValid", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, 0); }, OK},
  {"Lightfv_SpotExponentMinusZeroIsValid", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, -0.0f); }, OK},
  {"Lightfv_SpotCutoffMinus1", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, -1); }, IV},
  {"Lightfv_SpotCutoff91", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 91); }, IV},
  {"Lightfv_SpotCutoff90_01", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 90.01f); }, IV},
  {"Lightfv_SpotCutoff179_9", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 179.9f); }, IV},
  {"Lightfv_SpotCutoff180_1", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 180.1f); }, IV},
  {"Lightfv_SpotCutoff360", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 360); }, IV},
  {"Lightfv_SpotCutoff180IsValid", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 180); }, OK},
  {"Lightfv_SpotCutoff90IsValid", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 90); }, OK},
  {"Lightfv_SpotCutoff0IsValid", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 0); }, OK},
  {"Lightfv_ConstantAttenuationMinus0_1", lit_setup, [] { light1(GL_LIGHT2, GL_CONSTANT_ATTENUATION, -0.1f); }, IV},
  {"Lightfv_LinearAttenuationMinus0_1", lit_setup, [] { light1(GL_LIGHT2, GL_LINEAR_ATTENUATION, -0.1f); }, IV},
  {"Lightfv_QuadraticAttenuationMinus0_1", lit_setup, [] { light1(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, -0.1f); }, IV},
  {"Lightfv_QuadraticAttenuationMinusInfinity", lit_setup, [] { light1(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, -kInf); }, IV},
  {"Lightfv_ConstantAttenuation0IsValid", lit_setup, [] { light1(GL_LIGHT2, GL_CONSTANT_ATTENUATION, 0); }, OK},
  {"Lightfv_AmbientOutOfRangeIsValid", lit_setup, [] { light4(GL_LIGHT2, GL_AMBIENT, -2, 3, 0.5f, 7); }, OK},
  // Mesa's range tests (x < 0 || x > 128, ...) let a NaN through; GL 2.1 does not say. Ours follows.
  {"Lightfv_SpotExponentNaN", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_EXPONENT, kNaN); }, OK},
  {"Lightfv_SpotCutoffNaN", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, kNaN); }, OK},
  {"Lightfv_ConstantAttenuationNaN", lit_setup, [] { light1(GL_LIGHT2, GL_CONSTANT_ATTENUATION, kNaN); }, OK},
  {"Lightfv_InsideBeginEnd", lit_setup, inside([] { light4(GL_LIGHT2, GL_DIFFUSE, 1, 0, 0, 1); }), IO},
  {"Lightfv_BadPnameInsideBeginEnd", lit_setup, inside([] { light4(GL_LIGHT2, GL_EMISSION, 1, 0, 0, 1); }), IO},
  {"Lightfv_SpotCutoff91InsideBeginEnd", lit_setup, inside([] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 91); }), IO},
  {"Lightfv_FirstErrorIsKept", lit_setup, [] { light1(GL_LIGHT2, GL_SPOT_CUTOFF, 91); light1(GL_LIGHT0 + 9, GL_AMBIENT, 1); }, IV},

  {"Lightf_SpotExponentMinus1", lit_setup, [] { glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, -1); }, IV},
  {"Lightf_SpotExponent129", lit_setup, [] { glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 129); }, IV},
  {"Lightf_SpotCutoff91", lit_setup, [] { glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 91); }, IV},
  {"Lightf_SpotCutoff179_9", lit_setup, [] { glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 179.9f); }, IV},
  {"Lightf_SpotCutoff180IsValid", lit_setup, [] { glLightf(GL_LIGHT2, GL_SPOT_CUTOFF, 180); }, OK},
  {"Lightf_LinearAttenuationMinus0_1", lit_setup, [] { glLightf(GL_LIGHT2, GL_LINEAR_ATTENUATION, -0.1f); }, IV},
  {"Lightf_Light8", lit_setup, [] { glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1); }, IE},
  {"Lightf_PnameShininess", lit_setup, [] { glLightf(GL_LIGHT2, GL_SHININESS, 1); }, IE},
  // A vector parameter through glLightf / glLighti: GL 2.1 says GL_INVALID_ENUM; Mesa (light.c)
  // passes (param, 0, 0, 0) to the vector call and sets it. Ours follows Mesa.
  {"Lightf_AmbientVectorPname", lit_setup, [] { glLightf(GL_LIGHT2, GL_AMBIENT, 0.5f); }, OK},
  {"Lightf_PositionVectorPname", [] { lit_setup(); glTranslatef(1, 2, 3); }, [] { glLightf(GL_LIGHT2, GL_POSITION, 4); }, OK},
  {"Lightf_SpotDirectionVectorPname", [] { lit_setup(); glScalef(2, 3, 4); }, [] { glLightf(GL_LIGHT2, GL_SPOT_DIRECTION, 4); }, OK},
  {"Lightf_InsideBeginEnd", lit_setup, inside([] { glLightf(GL_LIGHT2, GL_SPOT_EXPONENT, 3); }), IO},
  {"Lightf_VectorPnameInsideBeginEnd", lit_setup, inside([] { glLightf(GL_LIGHT2, GL_AMBIENT, 0.5f); }), IO},

  {"Lighti_SpotExponentMinus1", lit_setup, [] { glLighti(GL_LIGHT2, GL_SPOT_EXPONENT, -1); }, IV},
  {"Lighti_SpotExponent129", lit_setup, [] { glLighti(GL_LIGHT2, GL_SPOT_EXPONENT, 129); }, IV},
  {"Lighti_SpotCutoff91", lit_setup, [] { glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 91); }, IV},
  {"Lighti_SpotCutoff179", lit_setup, [] { glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 179); }, IV},
  {"Lighti_SpotCutoff180IsValid", lit_setup, [] { glLighti(GL_LIGHT2, GL_SPOT_CUTOFF, 180); }, OK},
  {"Lighti_ConstantAttenuationMinus1", lit_setup, [] { glLighti(GL_LIGHT2, GL_CONSTANT_ATTENUATION, -1); }, IV},
  {"Lighti_Light8", lit_setup, [] { glLighti(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1); }, IE},
  {"Lighti_PnameEmission", lit_setup, [] { glLighti(GL_LIGHT2, GL_EMISSION, 1); }, IE},
  {"Lighti_DiffuseVectorPname", lit_setup, [] { glLighti(GL_LIGHT2, GL_DIFFUSE, 1 << 30); }, OK},
  {"Lighti_PositionVectorPname", [] { lit_setup(); glTranslatef(1, 2, 3); }, [] { glLighti(GL_LIGHT2, GL_POSITION, 4); }, OK},
  {"Lighti_InsideBeginEnd", lit_setup, inside([] { glLighti(GL_LIGHT2, GL_SPOT_EXPONENT, 3); }), IO},

  {"Lightiv_SpotExponent129", lit_setup, [] { lightiv4(GL_LIGHT2, GL_SPOT_EXPONENT, 129, 0, 0, 0); }, IV},
  {"Lightiv_SpotCutoff91", lit_setup, [] { lightiv4(GL_LIGHT2, GL_SPOT_CUTOFF, 91, 0, 0, 0); }, IV},
  {"Lightiv_QuadraticAttenuationMinus1", lit_setup, [] { lightiv4(GL_LIGHT2, GL_QUADRATIC_ATTENUATION, -1, 0, 0, 0); }, IV},
  {"Lightiv_Light8", lit_setup, [] { lightiv4(GL_LIGHT0 + 8, GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Lightiv_PnameShininess", lit_setup, [] { lightiv4(GL_LIGHT2, GL_SHININESS, 1, 1, 1, 1); }, IE},
  {"Lightiv_InsideBeginEnd", lit_setup, inside([] { lightiv4(GL_LIGHT2, GL_SPOT_CUTOFF, 30, 0, 0, 0); }), IO},
}), case_name);

// ---------------------------------------------------------------- glLightModel*

INSTANTIATE_TEST_SUITE_P(LightModel, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"LightModelfv_PnameAmbient", nullptr, [] { model4(GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"LightModelfv_PnameLight0", nullptr, [] { model4(GL_LIGHT0, 1, 1, 1, 1); }, IE},
  {"LightModelfv_ColorControlFlat", nullptr, [] { model4(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FLAT, 0, 0, 0); }, IE},
  {"LightModelfv_ColorControlZero", nullptr, [] { model4(GL_LIGHT_MODEL_COLOR_CONTROL, 0, 0, 0, 0); }, IE},
  {"LightModelfv_ColorControlSeparateIsValid", nullptr,
   [] { model4(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR, 0, 0, 0); }, OK},
  {"LightModelfv_TwoSideNonZeroIsValid", nullptr, [] { model4(GL_LIGHT_MODEL_TWO_SIDE, -0.5f, 0, 0, 0); }, OK},
  {"LightModelfv_InsideBeginEnd", nullptr, inside([] { model4(GL_LIGHT_MODEL_AMBIENT, 1, 0, 0, 1); }), IO},
  {"LightModelfv_BadPnameInsideBeginEnd", nullptr, inside([] { model4(GL_AMBIENT, 1, 0, 0, 1); }), IO},
  {"LightModelf_PnameAmbient", nullptr, [] { glLightModelf(GL_AMBIENT, 1); }, IE},
  {"LightModelf_ColorControlFlat", nullptr, [] { glLightModelf(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FLAT); }, IE},
  {"LightModelf_LocalViewerIsValid", nullptr, [] { glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, 1); }, OK},
  // As glLightf: Mesa sets (param, 0, 0, 0) without an error, where GL 2.1 says GL_INVALID_ENUM.
  {"LightModelf_AmbientVectorPname", nullptr, [] { glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.5f); }, OK},
  {"LightModeli_AmbientVectorPname", nullptr, [] { glLightModeli(GL_LIGHT_MODEL_AMBIENT, 1 << 30); }, OK},
  {"LightModelf_InsideBeginEnd", nullptr, inside([] { glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1); }), IO},
  {"LightModeli_PnameAmbient", nullptr, [] { glLightModeli(GL_AMBIENT, 1); }, IE},
  {"LightModeli_ColorControlFlat", nullptr, [] { glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FLAT); }, IE},
  {"LightModeli_ColorControlSeparateIsValid", nullptr,
   [] { glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR); }, OK},
  {"LightModeli_InsideBeginEnd", nullptr, inside([] { glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1); }), IO},
  {"LightModeliv_PnameAmbient", nullptr, [] { modeliv4(GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"LightModeliv_ColorControlFlat", nullptr, [] { modeliv4(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FLAT, 0, 0, 0); }, IE},
  {"LightModeliv_InsideBeginEnd", nullptr, inside([] { modeliv4(GL_LIGHT_MODEL_TWO_SIDE, 1, 0, 0, 0); }), IO},
}), case_name);

// ---------------------------------------------------------------- glMaterial*, glColorMaterial

INSTANTIATE_TEST_SUITE_P(Material, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"Materialfv_FaceLeft", lit_setup, [] { material4(GL_LEFT, GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Materialfv_FaceZero", lit_setup, [] { material4(0, GL_AMBIENT, 1, 1, 1, 1); }, IE},
  {"Materialfv_PnamePosition", lit_setup, [] { material4(GL_FRONT, GL_POSITION, 1, 1, 1, 1); }, IE},
  {"Materialfv_PnameSpotCutoff", lit_setup, [] { material4(GL_FRONT, GL_SPOT_CUTOFF, 1, 1, 1, 1); }, IE},
  {"Materialfv_BadFaceAndBadPname", lit_setup, [] { material4(GL_LEFT, GL_POSITION, 1, 1, 1, 1); }, IE},
  {"Materialfv_BadFaceAndShininessMinus1", lit_setup, [] { material4(GL_LEFT, GL_SHININESS, -1, 0, 0, 0); }, IE},
  {"Materialfv_ShininessMinus1", lit_setup, [] { material4(GL_FRONT, GL_SHININESS, -1, 0, 0, 0); }, IV},
  {"Materialfv_Shininess128_5", lit_setup, [] { material4(GL_BACK, GL_SHININESS, 128.5f, 0, 0, 0); }, IV},
  {"Materialfv_Shininess129FrontAndBack", lit_setup, [] { material4(GL_FRONT_AND_BACK, GL_SHININESS, 129, 0, 0, 0); }, IV},
  {"Materialfv_ShininessInfinity", lit_setup, [] { material4(GL_FRONT, GL_SHININESS, kInf, 0, 0, 0); }, IV},
  {"Materialfv_Shininess128IsValid", lit_setup, [] { material4(GL_FRONT, GL_SHININESS, 128, 0, 0, 0); }, OK},
  {"Materialfv_Shininess0IsValid", lit_setup, [] { material4(GL_BACK, GL_SHININESS, 0, 0, 0, 0); }, OK},
  {"Materialfv_EmissionOutOfRangeIsValid", lit_setup, [] { material4(GL_FRONT, GL_EMISSION, -1, 2, 0.5f, 3); }, OK},
  {"Materialfv_ColorIndexesIsValid", lit_setup, [] { material4(GL_FRONT_AND_BACK, GL_COLOR_INDEXES, 1, 2, 3, 0); }, OK},
  // glMaterial is allowed between glBegin and glEnd: its errors are its own, not INVALID_OPERATION.
  {"Materialfv_InsideBeginEndIsValid", lit_setup, inside([] { material4(GL_FRONT, GL_DIFFUSE, 0.1f, 0.2f, 0.3f, 1); }), OK},
  {"Materialfv_ShininessInsideBeginEndIsValid", lit_setup, inside([] { material4(GL_BACK, GL_SHININESS, 64, 0, 0, 0); }), OK},
  {"Materialfv_ShininessMinus1InsideBeginEnd", lit_setup, inside([] { material4(GL_FRONT, GL_SHININESS, -1, 0, 0, 0); }), IV},
  {"Materialfv_BadPnameInsideBeginEnd", lit_setup, inside([] { material4(GL_FRONT, GL_POSITION, 1, 1, 1, 1); }), IE},
  {"Materialfv_BadFaceInsideBeginEnd", lit_setup, inside([] { material4(GL_LEFT, GL_DIFFUSE, 1, 1, 1, 1); }), IE},

  {"Materialf_ShininessMinus1", lit_setup, [] { glMaterialf(GL_FRONT, GL_SHININESS, -1); }, IV},
  {"Materialf_Shininess128_5", lit_setup, [] { glMaterialf(GL_FRONT, GL_SHININESS, 128.5f); }, IV},
  {"Materialf_FaceLeft", lit_setup, [] { glMaterialf(GL_LEFT, GL_SHININESS, 5); }, IE},
  {"Materialf_PnamePosition", lit_setup, [] { glMaterialf(GL_FRONT, GL_POSITION, 5); }, IE},
  // A colour through glMaterialf / glMateriali: GL 2.1 says GL_INVALID_ENUM; Mesa raises nothing and
  // sets (param, ?, ?, ?), the last three uninitialised (api_loopback.c); ours sets (param, 0, 0, 0).
  {"Materialf_AmbientVectorPname", lit_setup, [] { glMaterialf(GL_FRONT, GL_AMBIENT, 0.5f); }, OK, Deviation::None,
   {"glGetMaterialfv(GL_FRONT, GL_AMBIENT)[1]", "glGetMaterialfv(GL_FRONT, GL_AMBIENT)[2]",
    "glGetMaterialfv(GL_FRONT, GL_AMBIENT)[3]"}},
  {"Materiali_DiffuseVectorPname", lit_setup, [] { glMateriali(GL_BACK, GL_DIFFUSE, 1 << 30); }, OK, Deviation::None,
   {"glGetMaterialfv(GL_BACK, GL_DIFFUSE)[1]", "glGetMaterialfv(GL_BACK, GL_DIFFUSE)[2]",
    "glGetMaterialfv(GL_BACK, GL_DIFFUSE)[3]"}},
  {"Materialfv_ShininessNaN", lit_setup, [] { material4(GL_FRONT, GL_SHININESS, kNaN, 0, 0, 0); }, OK},
  {"Materialf_InsideBeginEndIsValid", lit_setup, inside([] { glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 5); }), OK},
  {"Materialf_ShininessMinus1InsideBeginEnd", lit_setup, inside([] { glMaterialf(GL_FRONT, GL_SHININESS, -1); }), IV},

  {"Materiali_ShininessMinus1", lit_setup, [] { glMateriali(GL_FRONT, GL_SHININESS, -1); }, IV},
  {"Materiali_Shininess129", lit_setup, [] { glMateriali(GL_BACK, GL_SHININESS, 129); }, IV},
  {"Materiali_FaceLeft", lit_setup, [] { glMateriali(GL_LEFT, GL_SHININESS, 5); }, IE},
  {"Materiali_PnamePosition", lit_setup, [] { glMateriali(GL_FRONT, GL_POSITION, 5); }, IE},
  {"Materiali_Shininess20IsValid", lit_setup, [] { glMateriali(GL_FRONT, GL_SHININESS, 20); }, OK},
  {"Materiali_InsideBeginEndIsValid", lit_setup, inside([] { glMateriali(GL_BACK, GL_SHININESS, 7); }), OK},

  {"Materialiv_ShininessMinus1", lit_setup, [] { materialiv4(GL_FRONT, GL_SHININESS, -1, 0, 0, 0); }, IV},
  {"Materialiv_PnamePosition", lit_setup, [] { materialiv4(GL_FRONT, GL_POSITION, 1, 1, 1, 1); }, IE},
  {"Materialiv_FaceLeft", lit_setup, [] { materialiv4(GL_LEFT, GL_AMBIENT, 1, 1, 1, 1); }, IE},

  {"ColorMaterial_FaceLeft", nullptr, [] { glColorMaterial(GL_LEFT, GL_DIFFUSE); }, IE},
  {"ColorMaterial_ModePosition", nullptr, [] { glColorMaterial(GL_FRONT, GL_POSITION); }, IE},
  {"ColorMaterial_ModeShininess", nullptr, [] { glColorMaterial(GL_FRONT, GL_SHININESS); }, IE},
  {"ColorMaterial_ModeColorIndexes", nullptr, [] { glColorMaterial(GL_FRONT, GL_COLOR_INDEXES); }, IE},
  {"ColorMaterial_BadFaceAndBadMode", nullptr, [] { glColorMaterial(GL_LEFT, GL_SHININESS); }, IE},
  {"ColorMaterial_InsideBeginEnd", nullptr, inside([] { glColorMaterial(GL_BACK, GL_EMISSION); }), IO},
  {"ColorMaterial_BackSpecularIsValid", nullptr, [] { glColorMaterial(GL_BACK, GL_SPECULAR); }, OK},
  {"ColorMaterial_WhileEnabledIsValid", [] { glColor4f(0.1f, 0.2f, 0.3f, 0.4f); glEnable(GL_COLOR_MATERIAL); },
   [] { glColorMaterial(GL_FRONT, GL_EMISSION); }, OK},

  {"GetLightfv_Light8", nullptr, [] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetLightfv(GL_LIGHT0 + 8, GL_AMBIENT, v);
     for (float x : v) observe("untouched", x);
   }, IE},
  {"GetLightfv_PnameShininess", nullptr, [] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetLightfv(GL_LIGHT0, GL_SHININESS, v);
     for (float x : v) observe("untouched", x);
   }, IE},
  {"GetLightfv_InsideBeginEnd", nullptr, inside([] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetLightfv(GL_LIGHT0, GL_DIFFUSE, v);
     for (float x : v) observe("untouched", x);
   }), IO},
  {"GetMaterialfv_FrontAndBack", nullptr, [] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v);
     for (float x : v) observe("untouched", x);
   }, IE},
  {"GetMaterialfv_AmbientAndDiffuse", nullptr, [] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, v);
     for (float x : v) observe("untouched", x);
   }, IE},
  {"GetMaterialfv_PnamePosition", nullptr, [] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetMaterialfv(GL_BACK, GL_POSITION, v);
     for (float x : v) observe("untouched", x);
   }, IE},
  {"GetMaterialfv_InsideBeginEnd", nullptr, inside([] {
     GLfloat v[4] = {-1, -1, -1, -1};
     glGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
     for (float x : v) observe("untouched", x);
   }), IO},
}), case_name);

// ---------------------------------------------------------------- enables, shading, faces, depth

INSTANTIATE_TEST_SUITE_P(Enable, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"Enable_CapFlat", nullptr, [] { glEnable(GL_FLAT); }, IE},
  {"Enable_CapTriangles", nullptr, [] { glEnable(GL_TRIANGLES); }, IE},
  {"Enable_Light8", nullptr, [] { glEnable(GL_LIGHT0 + 8); }, IE},
  {"Enable_CapAmbient", nullptr, [] { glEnable(GL_AMBIENT); }, IE},
  // Mesa's glEnable takes the client arrays (GL 2.1: GL_INVALID_ENUM); ours follows.
  {"Enable_VertexArray", nullptr, [] { glEnable(GL_VERTEX_ARRAY); }, OK},
  {"Enable_TextureCoordArray", nullptr, [] { glEnable(GL_TEXTURE_COORD_ARRAY); }, OK},
  {"EnableClientState_Lighting2", nullptr, [] { glEnableClientState(GL_BLEND); }, IE},
  {"Enable_ColorTableImaging", nullptr, [] { glEnable(0x80D0); }, IE},
  {"Enable_HistogramImaging", nullptr, [] { glEnable(0x8024); }, IE},
  {"Enable_Convolution1DImaging", nullptr, [] { glEnable(0x8010); }, IE},
  {"Enable_ClipPlane8", nullptr, [] { glEnable(GL_CLIP_PLANE0 + 8); }, IE},
  {"Enable_InsideBeginEnd", nullptr, inside([] { glEnable(GL_LIGHTING); }), IO},
  {"Enable_BadCapInsideBeginEnd", nullptr, inside([] { glEnable(GL_FLAT); }), IO},
  {"Enable_BlendIsValid", nullptr, [] { glEnable(GL_BLEND); }, OK},
  {"Enable_FogIsValid", nullptr, [] { glEnable(GL_FOG); }, OK},
  {"Enable_Light7IsValid", nullptr, [] { glEnable(GL_LIGHT7); }, OK},
  {"Disable_CapFlat", [] { glEnable(GL_LIGHTING); }, [] { glDisable(GL_FLAT); }, IE},
  {"Disable_InsideBeginEnd", [] { glEnable(GL_LIGHTING); }, inside([] { glDisable(GL_LIGHTING); }), IO},
  {"Disable_DitherIsValid", nullptr, [] { glDisable(GL_DITHER); }, OK},
  {"IsEnabled_CapFlat", nullptr, [] { observe("glIsEnabled", glIsEnabled(GL_FLAT)); }, IE},
  {"IsEnabled_Light8", nullptr, [] { observe("glIsEnabled", glIsEnabled(GL_LIGHT0 + 8)); }, IE},
  {"IsEnabled_InsideBeginEnd", [] { glEnable(GL_LIGHTING); },
   inside([] { observe("glIsEnabled", glIsEnabled(GL_LIGHTING)); }), IO},

  {"EnableClientState_Lighting", nullptr, [] { glEnableClientState(GL_LIGHTING); }, IE},
  {"EnableClientState_Zero", nullptr, [] { glEnableClientState(0); }, IE},
  {"DisableClientState_Lighting", nullptr, [] { glDisableClientState(GL_LIGHTING); }, IE},
  {"EnableClientState_InsideBeginEnd", nullptr, inside([] { glEnableClientState(GL_VERTEX_ARRAY); }), IO},
  {"DisableClientState_InsideBeginEnd", [] { glEnableClientState(GL_NORMAL_ARRAY); },
   inside([] { glDisableClientState(GL_NORMAL_ARRAY); }), IO},
  {"EnableClientState_ColorArrayIsValid", nullptr, [] { glEnableClientState(GL_COLOR_ARRAY); }, OK},

  {"ShadeModel_Ccw", nullptr, [] { glShadeModel(GL_CCW); }, IE},
  {"ShadeModel_Zero", nullptr, [] { glShadeModel(0); }, IE},
  {"ShadeModel_InsideBeginEnd", nullptr, inside([] { glShadeModel(GL_FLAT); }), IO},
  {"ShadeModel_SameValueInsideBeginEnd", nullptr, inside([] { glShadeModel(GL_SMOOTH); }), IO},
  {"ShadeModel_FlatIsValid", nullptr, [] { glShadeModel(GL_FLAT); }, OK},
  {"FrontFace_Front", nullptr, [] { glFrontFace(GL_FRONT); }, IE},
  {"FrontFace_InsideBeginEnd", nullptr, inside([] { glFrontFace(GL_CW); }), IO},
  {"FrontFace_CwIsValid", nullptr, [] { glFrontFace(GL_CW); }, OK},
  {"CullFace_Cw", nullptr, [] { glCullFace(GL_CW); }, IE},
  {"CullFace_Left", nullptr, [] { glCullFace(GL_LEFT); }, IE},
  {"CullFace_InsideBeginEnd", nullptr, inside([] { glCullFace(GL_FRONT); }), IO},
  {"CullFace_FrontAndBackIsValid", nullptr, [] { glCullFace(GL_FRONT_AND_BACK); }, OK},
  {"DepthFunc_BelowNever", nullptr, [] { glDepthFunc(GL_NEVER - 1); }, IE},
  {"DepthFunc_AboveAlways", nullptr, [] { glDepthFunc(GL_ALWAYS + 1); }, IE},
  {"DepthFunc_InsideBeginEnd", nullptr, inside([] { glDepthFunc(GL_GEQUAL); }), IO},
  {"DepthFunc_GequalIsValid", nullptr, [] { glDepthFunc(GL_GEQUAL); }, OK},
}), case_name);

// ---------------------------------------------------------------- matrices, viewport, depth range

void push_n(GLenum mode, int n) {
  glMatrixMode(mode);
  for (int i = 0; i < n; ++i) {
    glPushMatrix();
    glTranslatef(float(i + 1), 0, 0);
  }
}

const GLfloat kMatF[16] = {1, 2, 0, 0, 0, 1, 3, 0, 0, 0, 1, 0, 4, 5, 6, 1};
const GLdouble kMatD[16] = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 1, 1, 1, 1};

INSTANTIATE_TEST_SUITE_P(Matrix, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"MatrixMode_ModelviewMatrix", nullptr, [] { glMatrixMode(GL_MODELVIEW_MATRIX); }, IE},
  {"MatrixMode_Zero", nullptr, [] { glMatrixMode(0); }, IE},
  {"MatrixMode_Color", nullptr, [] { glMatrixMode(0x1800); }, IE},
  {"MatrixMode_InsideBeginEnd", nullptr, inside([] { glMatrixMode(GL_PROJECTION); }), IO},
  {"MatrixMode_ProjectionIsValid", nullptr, [] { glMatrixMode(GL_PROJECTION); }, OK},
  {"LoadIdentity_InsideBeginEnd", [] { glTranslatef(1, 2, 3); }, inside([] { glLoadIdentity(); }), IO},
  {"LoadMatrixf_InsideBeginEnd", nullptr, inside([] { glLoadMatrixf(kMatF); }), IO},
  {"LoadMatrixd_InsideBeginEnd", nullptr, inside([] { glLoadMatrixd(kMatD); }), IO},
  {"MultMatrixf_InsideBeginEnd", nullptr, inside([] { glMultMatrixf(kMatF); }), IO},
  {"MultMatrixd_InsideBeginEnd", nullptr, inside([] { glMultMatrixd(kMatD); }), IO},
  {"PushMatrix_ModelviewOverflow", [] { push_n(GL_MODELVIEW, 31); }, [] { glPushMatrix(); }, SO},
  {"PushMatrix_ProjectionOverflow", [] { push_n(GL_PROJECTION, 31); }, [] { glPushMatrix(); }, SO},
  {"PushMatrix_ModelviewDepth32IsValid", [] { push_n(GL_MODELVIEW, 30); }, [] { glPushMatrix(); }, OK},
  {"PushMatrix_ProjectionFullModelviewIsValid", [] { push_n(GL_PROJECTION, 31); glMatrixMode(GL_MODELVIEW); },
   [] { glPushMatrix(); }, OK},
  {"PopMatrix_ModelviewUnderflow", [] { glTranslatef(1, 2, 3); }, [] { glPopMatrix(); }, SU},
  {"PopMatrix_ProjectionUnderflow", [] { glMatrixMode(GL_PROJECTION); glTranslatef(1, 2, 3); }, [] { glPopMatrix(); }, SU},
  {"PopMatrix_ProjectionUnderflowModelviewDeep", [] { push_n(GL_MODELVIEW, 3); glMatrixMode(GL_PROJECTION); },
   [] { glPopMatrix(); }, SU},
  {"PushMatrix_InsideBeginEnd", nullptr, inside([] { glPushMatrix(); }), IO},
  {"PopMatrix_InsideBeginEnd", [] { push_n(GL_MODELVIEW, 2); }, inside([] { glPopMatrix(); }), IO},
  {"Rotatef_InsideBeginEnd", nullptr, inside([] { glRotatef(30, 0, 0, 1); }), IO},
  {"Rotated_InsideBeginEnd", nullptr, inside([] { glRotated(30, 0, 0, 1); }), IO},
  {"Rotatef_ZeroAxisInsideBeginEnd", nullptr, inside([] { glRotatef(30, 0, 0, 0); }), IO},
  {"Scalef_InsideBeginEnd", nullptr, inside([] { glScalef(2, 2, 2); }), IO},
  {"Scaled_InsideBeginEnd", nullptr, inside([] { glScaled(2, 2, 2); }), IO},
  {"Translatef_InsideBeginEnd", nullptr, inside([] { glTranslatef(1, 2, 3); }), IO},
  {"Translated_InsideBeginEnd", nullptr, inside([] { glTranslated(1, 2, 3); }), IO},
  {"Ortho_LeftEqualsRight", nullptr, [] { glOrtho(1, 1, -1, 1, -1, 1); }, IV},
  {"Ortho_BottomEqualsTop", nullptr, [] { glOrtho(-1, 1, 2, 2, -1, 1); }, IV},
  {"Ortho_NearEqualsFar", nullptr, [] { glOrtho(-1, 1, -1, 1, 3, 3); }, IV},
  {"Ortho_InsideBeginEnd", nullptr, inside([] { glOrtho(-1, 1, -1, 1, -1, 1); }), IO},
  {"Ortho_InvalidInsideBeginEnd", nullptr, inside([] { glOrtho(1, 1, -1, 1, -1, 1); }), IO},
  {"Ortho_NegativeNearIsValid", nullptr, [] { glOrtho(-2, 3, -1, 4, -5, 6); }, OK},
  {"Frustum_NearZero", nullptr, [] { glFrustum(-1, 1, -1, 1, 0, 10); }, IV},
  {"Frustum_NearNegative", nullptr, [] { glFrustum(-1, 1, -1, 1, -1, 10); }, IV},
  {"Frustum_FarZero", nullptr, [] { glFrustum(-1, 1, -1, 1, 1, 0); }, IV},
  {"Frustum_FarNegative", nullptr, [] { glFrustum(-1, 1, -1, 1, 1, -10); }, IV},
  {"Frustum_NearEqualsFar", nullptr, [] { glFrustum(-1, 1, -1, 1, 2, 2); }, IV},
  {"Frustum_LeftEqualsRight", nullptr, [] { glFrustum(1, 1, -1, 1, 1, 10); }, IV},
  {"Frustum_BottomEqualsTop", nullptr, [] { glFrustum(-1, 1, 1, 1, 1, 10); }, IV},
  {"Frustum_InsideBeginEnd", nullptr, inside([] { glFrustum(-1, 1, -1, 1, 1, 10); }), IO},
  {"Frustum_NearBeyondFarIsValid", nullptr, [] { glFrustum(-1, 1, -1, 1, 10, 1); }, OK},
  {"Viewport_NegativeWidth", nullptr, [] { glViewport(0, 0, -1, 10); }, IV},
  {"Viewport_NegativeHeight", nullptr, [] { glViewport(0, 0, 10, -1); }, IV},
  {"Viewport_InsideBeginEnd", nullptr, inside([] { glViewport(1, 2, 3, 4); }), IO},
  {"Viewport_NegativeOriginIsValid", nullptr, [] { glViewport(-5, -6, 7, 8); }, OK},
  {"Viewport_HugeIsClamped", nullptr, [] { glViewport(0, 0, 100000, 100000); }, OK},
  {"DepthRange_InsideBeginEnd", nullptr, inside([] { glDepthRange(0.25, 0.75); }), IO},
  {"DepthRange_OutOfRangeIsClamped", nullptr, [] { glDepthRange(-1, 2); }, OK},
  {"DepthRange_ReversedIsValid", nullptr, [] { glDepthRange(0.9, 0.1); }, OK},
}), case_name);

// ---------------------------------------------------------------- client arrays and drawing

const GLfloat kVerts[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
const GLfloat kNormals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
const GLubyte kColors[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 255};
const GLushort kIndices[] = {0, 1, 2, 2, 1, 3};

void arrays_setup() {
  glVertexPointer(3, GL_FLOAT, 12, kVerts);
  glNormalPointer(GL_FLOAT, 0, kNormals);
  glColorPointer(4, GL_UNSIGNED_BYTE, 4, kColors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
}

INSTANTIATE_TEST_SUITE_P(Arrays, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"VertexPointer_Size1", arrays_setup, [] { glVertexPointer(1, GL_FLOAT, 0, kVerts); }, IV},
  {"VertexPointer_Size5", arrays_setup, [] { glVertexPointer(5, GL_FLOAT, 0, kVerts); }, IV},
  {"VertexPointer_Size0", arrays_setup, [] { glVertexPointer(0, GL_FLOAT, 0, kVerts); }, IV},
  {"VertexPointer_TypeByte", arrays_setup, [] { glVertexPointer(3, GL_BYTE, 0, kVerts); }, IE},
  {"VertexPointer_TypeUnsignedByte", arrays_setup, [] { glVertexPointer(3, GL_UNSIGNED_BYTE, 0, kVerts); }, IE},
  {"VertexPointer_TypeUnsignedShort", arrays_setup, [] { glVertexPointer(3, GL_UNSIGNED_SHORT, 0, kVerts); }, IE},
  {"VertexPointer_TypeUnsignedInt", arrays_setup, [] { glVertexPointer(3, GL_UNSIGNED_INT, 0, kVerts); }, IE},
  {"VertexPointer_TypeNotAType", arrays_setup, [] { glVertexPointer(3, GL_LIGHTING, 0, kVerts); }, IE},
  // A negative stride: Mesa records GL_INVALID_VALUE and sets the pointer anyway (stride -1 read
  // back); with another error in the same call it sets nothing.
  {"VertexPointer_StrideMinus1", arrays_setup, [] { glVertexPointer(3, GL_FLOAT, -1, kVerts); }, IV, Deviation::MesaAppliesOnError},
  {"VertexPointer_Size1TypeByte", arrays_setup, [] { glVertexPointer(1, GL_BYTE, 0, kVerts); }, IE},
  {"VertexPointer_Size5StrideMinus1", arrays_setup, [] { glVertexPointer(5, GL_FLOAT, -1, kVerts); }, IV},
  {"VertexPointer_TypeByteStrideMinus1", arrays_setup, [] { glVertexPointer(3, GL_BYTE, -4, kVerts); }, IV},
  {"VertexPointer_InsideBeginEnd", arrays_setup, inside([] { glVertexPointer(2, GL_SHORT, 4, kVerts); }), IO},
  {"VertexPointer_Size2ShortIsValid", arrays_setup, [] { glVertexPointer(2, GL_SHORT, 4, kVerts); }, OK},
  {"VertexPointer_Size4DoubleIsValid", arrays_setup, [] { glVertexPointer(4, GL_DOUBLE, 0, kVerts); }, OK},
  {"NormalPointer_TypeUnsignedByte", arrays_setup, [] { glNormalPointer(GL_UNSIGNED_BYTE, 0, kNormals); }, IE},
  {"NormalPointer_TypeUnsignedShort", arrays_setup, [] { glNormalPointer(GL_UNSIGNED_SHORT, 0, kNormals); }, IE},
  {"NormalPointer_TypeUnsignedInt", arrays_setup, [] { glNormalPointer(GL_UNSIGNED_INT, 0, kNormals); }, IE},
  {"NormalPointer_StrideMinus1", arrays_setup, [] { glNormalPointer(GL_FLOAT, -1, kNormals); }, IV, Deviation::MesaAppliesOnError},
  {"NormalPointer_BadTypeStrideMinus1", arrays_setup, [] { glNormalPointer(GL_UNSIGNED_INT, -1, kNormals); }, IV},
  {"NormalPointer_InsideBeginEnd", arrays_setup, inside([] { glNormalPointer(GL_BYTE, 3, kNormals); }), IO},
  {"NormalPointer_ByteIsValid", arrays_setup, [] { glNormalPointer(GL_BYTE, 3, kNormals); }, OK},
  {"ColorPointer_Size2", arrays_setup, [] { glColorPointer(2, GL_FLOAT, 0, kVerts); }, IV},
  {"ColorPointer_Size5", arrays_setup, [] { glColorPointer(5, GL_FLOAT, 0, kVerts); }, IV},
  {"ColorPointer_TypeNotAType", arrays_setup, [] { glColorPointer(4, GL_LIGHTING, 0, kVerts); }, IE},
  {"ColorPointer_StrideMinus1", arrays_setup, [] { glColorPointer(4, GL_FLOAT, -1, kVerts); }, IV, Deviation::MesaAppliesOnError},
  {"ColorPointer_Size2TypeNotAType", arrays_setup, [] { glColorPointer(2, GL_LIGHTING, 0, kVerts); }, IE},
  {"ColorPointer_InsideBeginEnd", arrays_setup, inside([] { glColorPointer(3, GL_FLOAT, 0, kVerts); }), IO},
  {"ColorPointer_Size3FloatIsValid", arrays_setup, [] { glColorPointer(3, GL_FLOAT, 16, kVerts); }, OK},

  // Modes 0xA-0xD are GL 3.2's adjacency primitives, which Mesa's context accepts; 0xE is GL_PATCHES.
  {"DrawArrays_LinesAdjacency", arrays_setup, [] { glDrawArrays(0xA, 0, 4); }, OK},
  {"DrawArrays_TriangleStripAdjacency", arrays_setup, [] { glDrawArrays(0xD, 0, 4); }, OK},
  {"DrawArrays_Patches", arrays_setup, [] { glDrawArrays(0xE, 0, 3); }, IO},
  {"DrawArrays_Mode0xF", arrays_setup, [] { glDrawArrays(0xF, 0, 3); }, IE},
  {"DrawArrays_Mode0xFCountMinus1", arrays_setup, [] { glDrawArrays(0xF, 0, -1); }, IV},
  {"DrawArrays_PatchesCountMinus1", arrays_setup, [] { glDrawArrays(0xE, 0, -1); }, IV},
  {"DrawArrays_ModeHuge", arrays_setup, [] { glDrawArrays(0x7FFF, 0, 3); }, IE},
  {"DrawArrays_CountMinus1", arrays_setup, [] { glDrawArrays(GL_TRIANGLES, 0, -1); }, IV},
  // A negative first: no error in GL 2.1 nor in Mesa; ours draws nothing.
  {"DrawArrays_FirstMinus1", arrays_setup, [] { glDrawArrays(GL_TRIANGLES, -1, 3); }, OK},
  {"DrawArrays_FirstMinus1CountMinus1", arrays_setup, [] { glDrawArrays(GL_TRIANGLES, -1, -1); }, IV},
  {"DrawArrays_InsideBeginEnd", arrays_setup, inside([] { glDrawArrays(GL_TRIANGLES, 0, 3); }), IO},
  {"DrawArrays_BadModeInsideBeginEnd", arrays_setup, inside([] { glDrawArrays(GL_POLYGON + 1, 0, 3); }), IO},
  {"DrawArrays_CountZeroIsValid", arrays_setup, [] { glDrawArrays(GL_TRIANGLES, 0, 0); }, OK},
  {"DrawArrays_IsValid", arrays_setup, [] { glDrawArrays(GL_TRIANGLE_STRIP, 0, 4); }, OK},
  {"DrawArrays_NoVertexArrayIsValid", nullptr, [] { glDrawArrays(GL_TRIANGLES, 0, 3); }, OK},
  {"DrawElements_LinesAdjacency", arrays_setup, [] { glDrawElements(0xA, 4, GL_UNSIGNED_SHORT, kIndices); }, OK},
  {"DrawElements_Patches", arrays_setup, [] { glDrawElements(0xE, 3, GL_UNSIGNED_SHORT, kIndices); }, IO},
  {"DrawElements_PatchesBadType", arrays_setup, [] { glDrawElements(0xE, 3, GL_FLOAT, kIndices); }, IO},
  {"DrawElements_Mode0xF", arrays_setup, [] { glDrawElements(0xF, 3, GL_UNSIGNED_SHORT, kIndices); }, IE},
  {"DrawElements_CountMinus1", arrays_setup, [] { glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_SHORT, kIndices); }, IV},
  {"DrawElements_TypeInt", arrays_setup, [] { glDrawElements(GL_TRIANGLES, 3, GL_INT, kIndices); }, IE},
  {"DrawElements_TypeShort", arrays_setup, [] { glDrawElements(GL_TRIANGLES, 3, GL_SHORT, kIndices); }, IE},
  {"DrawElements_TypeFloat", arrays_setup, [] { glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, kIndices); }, IE},
  {"DrawElements_BadModeBadType", arrays_setup, [] { glDrawElements(0xF, 3, GL_FLOAT, kIndices); }, IE},
  {"DrawElements_CountMinus1BadType", arrays_setup, [] { glDrawElements(GL_TRIANGLES, -1, GL_FLOAT, kIndices); }, IV},
  {"DrawElements_BadModeCountMinus1", arrays_setup, [] { glDrawElements(0xF, -1, GL_UNSIGNED_SHORT, kIndices); }, IV},
  {"DrawElements_InsideBeginEnd", arrays_setup, inside([] { glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, kIndices); }), IO},
  {"DrawElements_IsValid", arrays_setup, [] { glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, kIndices); }, OK},
  {"ArrayElement_InsideBeginEndIsValid", arrays_setup, inside([] { glArrayElement(0); glArrayElement(1); glArrayElement(2); }), OK},
  // A negative index: no error in GL 2.1 nor in Mesa, which reads before the arrays.
  {"ArrayElement_Minus1InsideBeginEnd", arrays_setup, inside([] { glArrayElement(-1); }), OK, Deviation::MesaReadsOutOfBounds},
  {"ArrayElement_Minus1OutsideBeginEnd", arrays_setup, [] { glArrayElement(-1); }, OK, Deviation::MesaReadsOutOfBounds},
  {"ArrayElement_OutsideBeginEnd", arrays_setup, [] { glArrayElement(1); }, OK},
  // Outside glBegin/glEnd, glArrayElement still sets the current normal and colour.
  {"ArrayElement_OutsideBeginEndSetsCurrentValues", [] { arrays_setup(); glNormalPointer(GL_FLOAT, 0, kVerts); glEnableClientState(GL_COLOR_ARRAY); },
   [] { glArrayElement(3); }, OK},
}), case_name);

// ---------------------------------------------------------------- glBegin/glEnd, glGetError

INSTANTIATE_TEST_SUITE_P(BeginEnd, Errors, ::testing::ValuesIn(std::vector<Case>{
  // As glDrawArrays: the adjacency modes are accepted (Mesa), GL_PATCHES is GL_INVALID_OPERATION.
  {"Begin_LinesAdjacency", nullptr, [] { glBegin(0xA); glVertex3f(0, 0, 0); glEnd(); }, OK},
  {"Begin_Patches", nullptr, [] { glBegin(0xE); glVertex3f(0, 0, 0); glEnd(); }, IO},
  {"Begin_Mode0xF", nullptr, [] { glBegin(0xF); glVertex3f(0, 0, 0); glEnd(); }, IE},
  {"Begin_ModeHuge", nullptr, [] { glBegin(0xFFFF); }, IE},
  {"Begin_Nested", nullptr, [] { glBegin(GL_POINTS); glBegin(GL_LINES); glEnd(); }, IO},
  {"Begin_NestedBadMode", nullptr, [] { glBegin(GL_POINTS); glBegin(GL_POLYGON + 1); glEnd(); }, IO},
  {"End_WithoutBegin", nullptr, [] { glEnd(); }, IO},
  {"End_Twice", nullptr, [] { glBegin(GL_POINTS); glEnd(); glEnd(); }, IO},
  {"BeginEnd_EmptyIsValid", nullptr, [] { glBegin(GL_TRIANGLES); glEnd(); }, OK},
  {"GetError_InsideBeginEnd", nullptr, [] {
     glBegin(GL_POINTS);
     observe("glGetError inside", glGetError());
     glEnd();
   }, IO},
  {"GetError_InsideBeginEndKeepsEarlierError", nullptr, [] {
     glLineWidth(-1);
     glBegin(GL_POINTS);
     observe("glGetError inside", glGetError());
     glEnd();
   }, IV},
  {"GetFloatv_InsideBeginEnd", nullptr, inside([] {
     GLfloat v[16];
     std::fill(v, v + 16, -1.f);
     glGetFloatv(GL_LINE_WIDTH, v);
     observe("untouched", v[0]);
   }), IO},
  {"GetIntegerv_InsideBeginEnd", nullptr, inside([] {
     GLint v[16];
     std::fill(v, v + 16, -1);
     glGetIntegerv(GL_MATRIX_MODE, v);
     observe("untouched", v[0]);
   }), IO},
  {"GetDoublev_InsideBeginEnd", nullptr, inside([] {
     GLdouble v[16];
     std::fill(v, v + 16, -1.);
     glGetDoublev(GL_DEPTH_RANGE, v);
     observe("untouched", v[0]);
   }), IO},
  {"GetFloatv_PnameAmbient", nullptr, [] {
     GLfloat v[16];
     std::fill(v, v + 16, -1.f);
     glGetFloatv(GL_AMBIENT, v);
     observe("untouched", v[0]);
   }, IE},
  {"GetIntegerv_PnameZero", nullptr, [] {
     GLint v[16];
     std::fill(v, v + 16, -1);
     glGetIntegerv(0, v);
     observe("untouched", v[0]);
   }, IE},
  {"GetDoublev_PnameLight8", nullptr, [] {
     GLdouble v[16];
     std::fill(v, v + 16, -1.);
     glGetDoublev(GL_LIGHT0 + 8, v);
     observe("untouched", v[0]);
   }, IE},
}), case_name);

// ---------------------------------------------------------------- feedback, clear, lines, pixels, strings

GLfloat g_feedback[64];

INSTANTIATE_TEST_SUITE_P(Misc, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"FeedbackBuffer_TypeRgba", nullptr, [] { glFeedbackBuffer(64, GL_RGBA, g_feedback); }, IE},
  {"FeedbackBuffer_SizeMinus1", nullptr, [] { glFeedbackBuffer(-1, GL_3D, g_feedback); }, IV},
  {"FeedbackBuffer_BadTypeSizeMinus1", nullptr, [] { glFeedbackBuffer(-1, GL_RGBA, g_feedback); }, IV},
  {"FeedbackBuffer_InFeedbackMode", [] { glFeedbackBuffer(64, GL_3D, g_feedback); glRenderMode(GL_FEEDBACK); },
   [] { glFeedbackBuffer(32, GL_2D, g_feedback); }, IO},
  {"FeedbackBuffer_InsideBeginEnd", nullptr, inside([] { glFeedbackBuffer(64, GL_3D, g_feedback); }), IO},
  {"FeedbackBuffer_IsValid", nullptr, [] { glFeedbackBuffer(64, GL_3D_COLOR, g_feedback); }, OK},
  {"RenderMode_Zero", nullptr, [] { observe("glRenderMode", glRenderMode(0)); }, IE},
  {"RenderMode_Lighting", nullptr, [] { observe("glRenderMode", glRenderMode(GL_LIGHTING)); }, IE},
  // Mesa records GL_INVALID_OPERATION and switches the mode anyway (feedback.c).
  {"RenderMode_FeedbackWithoutBuffer", nullptr, [] { observe("glRenderMode", glRenderMode(GL_FEEDBACK)); }, IO,
   Deviation::MesaAppliesOnError},
  {"RenderMode_FeedbackWithEmptyBuffer", [] { glFeedbackBuffer(0, GL_3D, g_feedback); },
   [] { observe("glRenderMode", glRenderMode(GL_FEEDBACK)); }, IO, Deviation::MesaAppliesOnError},
  {"RenderMode_SelectWithoutBuffer", nullptr, [] { observe("glRenderMode", glRenderMode(GL_SELECT)); }, IO,
   Deviation::MesaAppliesOnError},
  {"FeedbackBuffer_NullBuffer", nullptr, [] { glFeedbackBuffer(8, GL_3D, nullptr); }, IV},
  // Mesa records GL_INVALID_VALUE and sets the buffer size to 0 (feedback.c); ours keeps the buffer.
  {"FeedbackBuffer_NullBufferAfterBuffer", [] { glFeedbackBuffer(64, GL_3D, g_feedback); },
   [] { glFeedbackBuffer(8, GL_3D, nullptr); }, IV, Deviation::MesaAppliesOnError},
  {"FeedbackBuffer_NullBufferSize0IsValid", nullptr, [] { glFeedbackBuffer(0, GL_3D, nullptr); }, OK},
  {"RenderMode_InsideBeginEnd", [] { glFeedbackBuffer(64, GL_3D, g_feedback); },
   inside([] { observe("glRenderMode", glRenderMode(GL_FEEDBACK)); }), IO},
  {"RenderMode_BadModeInFeedback", [] { glFeedbackBuffer(64, GL_3D, g_feedback); glRenderMode(GL_FEEDBACK); },
   [] { observe("glRenderMode", glRenderMode(GL_LIGHTING)); }, IE},
  {"RenderMode_FeedbackIsValid", [] { glFeedbackBuffer(64, GL_3D, g_feedback); },
   [] { observe("glRenderMode", glRenderMode(GL_FEEDBACK)); }, OK},
  {"RenderMode_LeaveFeedbackCounts", [] { glFeedbackBuffer(64, GL_2D, g_feedback); glRenderMode(GL_FEEDBACK); },
   [] {
     glBegin(GL_POINTS);
     glVertex3f(0, 0, 0);
     glEnd();
     observe("glRenderMode", glRenderMode(GL_RENDER));
   }, OK},

  {"Clear_Bit0", nullptr, [] { glClear(0x1); }, IV},
  {"Clear_ColorAndHighBit", nullptr, [] { glClear(GL_COLOR_BUFFER_BIT | 0x80000000u); }, IV},
  {"Clear_InsideBeginEnd", nullptr, inside([] { glClear(GL_COLOR_BUFFER_BIT); }), IO},
  {"Clear_AllBuffersIsValid", nullptr,
   [] { glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT); }, OK},
  {"Clear_NothingIsValid", nullptr, [] { glClear(0); }, OK},

  {"LineWidth_Zero", [] { glLineWidth(3); }, [] { glLineWidth(0); }, IV},
  {"LineWidth_Negative", [] { glLineWidth(3); }, [] { glLineWidth(-2); }, IV},
  {"LineWidth_MinusInfinity", [] { glLineWidth(3); }, [] { glLineWidth(-kInf); }, IV},
  {"LineWidth_NaN", [] { glLineWidth(3); }, [] { glLineWidth(kNaN); }, OK},
  {"LineWidth_InsideBeginEnd", nullptr, inside([] { glLineWidth(2); }), IO},
  {"LineWidth_SmallIsValid", nullptr, [] { glLineWidth(0.001f); }, OK},
  {"LineWidth_LargeIsValid", nullptr, [] { glLineWidth(100); }, OK},
  {"PointSize_Zero", [] { glPointSize(3); }, [] { glPointSize(0); }, IV},
  {"PointSize_Negative", [] { glPointSize(3); }, [] { glPointSize(-2); }, IV},
  {"PointSize_MinusInfinity", [] { glPointSize(3); }, [] { glPointSize(-kInf); }, IV},
  {"PointSize_NaN", [] { glPointSize(3); }, [] { glPointSize(kNaN); }, OK},
  {"PointSize_InsideBeginEnd", nullptr, inside([] { glPointSize(2); }), IO},
  {"PointSize_SmallIsValid", nullptr, [] { glPointSize(0.001f); }, OK},
  {"PointSize_LargeIsValid", nullptr, [] { glPointSize(1000); }, OK},

  {"PixelStorei_PnameLighting", nullptr, [] { glPixelStorei(GL_LIGHTING, 4); }, IE},
  {"PixelStorei_PackAlignment3", nullptr, [] { glPixelStorei(GL_PACK_ALIGNMENT, 3); }, IV},
  {"PixelStorei_PackAlignment0", nullptr, [] { glPixelStorei(GL_PACK_ALIGNMENT, 0); }, IV},
  {"PixelStorei_PackAlignment16", nullptr, [] { glPixelStorei(GL_PACK_ALIGNMENT, 16); }, IV},
  {"PixelStorei_PackAlignmentMinus4", nullptr, [] { glPixelStorei(GL_PACK_ALIGNMENT, -4); }, IV},
  {"PixelStorei_UnpackAlignment5", nullptr, [] { glPixelStorei(GL_UNPACK_ALIGNMENT, 5); }, IV},
  {"PixelStorei_InsideBeginEnd", nullptr, inside([] { glPixelStorei(GL_PACK_ALIGNMENT, 1); }), IO},
  {"PixelStorei_PackAlignment8IsValid", nullptr, [] { glPixelStorei(GL_PACK_ALIGNMENT, 8); }, OK},
  {"PixelStorei_UnpackAlignment1IsValid", nullptr, [] { glPixelStorei(GL_UNPACK_ALIGNMENT, 1); }, OK},
  {"PixelStorei_PackRowLengthMinus1", nullptr, [] { glPixelStorei(GL_PACK_ROW_LENGTH, -1); }, IV},
  {"PixelStorei_UnpackSkipRowsMinus1", nullptr, [] { glPixelStorei(GL_UNPACK_SKIP_ROWS, -1); }, IV},
  {"PixelStorei_PackRowLength0IsValid", nullptr, [] { glPixelStorei(GL_PACK_ROW_LENGTH, 0); }, OK},
  {"PixelStorei_UnpackSwapBytesIsValid", nullptr, [] { glPixelStorei(GL_UNPACK_SWAP_BYTES, 0); }, OK},

  {"GetString_Lighting", nullptr, [] { observe("null", glGetString(GL_LIGHTING) == nullptr); }, IE},
  {"GetString_Zero", nullptr, [] { observe("null", glGetString(0) == nullptr); }, IE},
  {"GetString_InsideBeginEnd", nullptr, inside([] { observe("null", glGetString(GL_VENDOR) == nullptr); }), IO},
  {"GetString_VendorIsValid", nullptr, [] { observe("null", glGetString(GL_VENDOR) == nullptr); }, OK},
  {"GetString_VersionIsValid", nullptr, [] { observe("null", glGetString(GL_VERSION) == nullptr); }, OK},
  {"GetString_RendererIsValid", nullptr, [] { observe("null", glGetString(GL_RENDERER) == nullptr); }, OK},
  {"GetString_ShadingLanguageVersionIsValid", nullptr,
   [] { observe("null", glGetString(GL_SHADING_LANGUAGE_VERSION) == nullptr); }, OK},
  {"GetString_ExtensionsIsValid", nullptr, [] { observe("null", glGetString(GL_EXTENSIONS) == nullptr); }, OK},
}), case_name);

// glFog and glPolygonOffset (Mesa's fog.c and polygon.c): every pname through the four glFog
// forms, the values each accepts, and the errors; every state test reads the fog and offset glGet
// names back (harness.h get_pnames).
const GLfloat kFogColor[4] = {0.25f, -0.5f, 1.5f, 0.75f};
const GLint kFogColorI[4] = {INT_MAX / 2, -INT_MAX, INT_MAX, 0};
INSTANTIATE_TEST_SUITE_P(Fog, Errors, ::testing::ValuesIn(std::vector<Case>{
  {"Fogi_ModeLinear", nullptr, [] { glFogi(GL_FOG_MODE, GL_LINEAR); }, OK},
  {"Fogf_ModeExp2", nullptr, [] { glFogf(GL_FOG_MODE, GLfloat(GL_EXP2)); }, OK},
  {"Fogi_ModeBad", nullptr, [] { glFogi(GL_FOG_MODE, GL_LINE); }, IE},
  {"Fogf_DensityNegative", nullptr, [] { glFogf(GL_FOG_DENSITY, -0.5f); }, IV},
  {"Fogf_DensityZero", nullptr, [] { glFogf(GL_FOG_DENSITY, 0); }, OK},
  {"Fogf_DensityNaN", nullptr, [] { glFogf(GL_FOG_DENSITY, kNaN); }, OK},
  {"Fogf_Density", nullptr, [] { glFogf(GL_FOG_DENSITY, 2.75f); }, OK},
  {"Fogf_StartEnd", nullptr, [] { glFogf(GL_FOG_START, -3.5f); glFogf(GL_FOG_END, 1e6f); }, OK},
  {"Fogi_StartEnd", nullptr, [] { glFogi(GL_FOG_START, 7); glFogi(GL_FOG_END, -2); }, OK},
  {"Fogf_Index", nullptr, [] { glFogf(GL_FOG_INDEX, 3.6f); }, OK},
  {"Fogfv_ColorClamped", nullptr, [] { glFogfv(GL_FOG_COLOR, kFogColor); }, OK},
  {"Fogiv_Color", nullptr, [] { glFogiv(GL_FOG_COLOR, kFogColorI); }, OK},
  {"Fogiv_Mode", nullptr, [] { const GLint m = GL_EXP2; glFogiv(GL_FOG_MODE, &m); }, OK},
  {"Fogiv_Density", nullptr, [] { const GLint d = 3; glFogiv(GL_FOG_DENSITY, &d); }, OK},
  {"Fogi_CoordSrcFogCoord", nullptr, [] { glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD); }, OK},
  {"Fogi_CoordSrcFragmentDepth", nullptr, [] { glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH); }, OK},
  {"Fogi_CoordSrcBad", nullptr, [] { glFogi(GL_FOG_COORD_SRC, GL_FOG); }, IE},
  {"Fogf_BadPname", nullptr, [] { glFogf(GL_FOG_HINT, 1); }, IE},
  {"Fogiv_BadPname", nullptr, [] { const GLint v[4] = {1, 2, 3, 4}; glFogiv(GL_FOG, v); }, IE},
  {"Fogf_InsideBeginEnd", nullptr, inside([] { glFogf(GL_FOG_START, 2); }), IO},
  {"Fogfv_InsideBeginEnd", nullptr, inside([] { glFogfv(GL_FOG_COLOR, kFogColor); }), IO},
  {"PolygonOffset", nullptr, [] { glPolygonOffset(-1.5f, 4.25f); }, OK},
  {"PolygonOffset_Large", nullptr, [] { glPolygonOffset(1e30f, -1e30f); }, OK},
  {"PolygonOffset_InsideBeginEnd", nullptr, inside([] { glPolygonOffset(1, 1); }), IO},
  {"Enable_PolygonOffsetFill", nullptr, [] { glEnable(GL_POLYGON_OFFSET_FILL); }, OK},
}), case_name);

// A glRenderMode with a bad mode while in feedback mode: Mesa resets the feedback count before it
// checks the mode (feedback.c), so the next glRenderMode(GL_RENDER) returns 0; GL 2.1 section 2.5
// says the failed call has no effect, and ours returns the count of what was fed back (3 values
// for a GL_2D point: the token, x and y).
TEST(ErrorsKnownDeviation, BadRenderModeInFeedbackKeepsTheCount) {
  auto run_side = [](Side s) {
    fresh_context(s);
    glFeedbackBuffer(64, GL_2D, g_feedback);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0);
    glEnd();
    EXPECT_EQ(glRenderMode(GL_LIGHTING), 0) << side_name(s);
    EXPECT_EQ(enum_name(glGetError()), "GL_INVALID_ENUM") << side_name(s);
    return glRenderMode(GL_RENDER);
  };
  EXPECT_EQ(run_side(kMesa), 0) << "Mesa no longer resets the count on a bad mode: make ours agree again";
  EXPECT_EQ(run_side(kSoft), 3);
}

// ---------------------------------------------------------------- every capability, every pixel-store value

// glEnable then glDisable for every capability glIsEnabled answers for (glEnableClientState and
// glDisableClientState for the client arrays): no error, and the state read back agrees.
std::vector<Case> capability_rows() {
  std::vector<Case> rows;
  for (GLenum cap : caps()) {
    std::string name = enum_name(cap).substr(3);
    if (is_client_array(cap)) {
      rows.push_back({"EnableClientState_" + name, nullptr, [cap] { glEnableClientState(cap); }, OK});
      rows.push_back({"DisableClientState_" + name, [cap] { glEnableClientState(cap); },
                      [cap] { glDisableClientState(cap); }, OK});
    } else {
      rows.push_back({"Enable_" + name, nullptr, [cap] { glEnable(cap); }, OK});
      rows.push_back({"Disable_" + name, [cap] { glEnable(cap); }, [cap] { glDisable(cap); }, OK});
    }
  }
  return rows;
}
INSTANTIATE_TEST_SUITE_P(Capability, Errors, ::testing::ValuesIn(capability_rows()), case_name);

// glPixelStorei for every GL 2.1 pname, with -1, 0, 3 and 8: alignments take 1, 2, 4 or 8
// (GL_INVALID_VALUE otherwise), lengths and skips any value >= 0, the booleans any value.
std::vector<Case> pixel_store_rows() {
  struct P {
    GLenum pname;
    const char* name;
    enum { Boolean, Count, Alignment } kind;
  };
  const P pnames[] = {
      {GL_PACK_SWAP_BYTES, "PackSwapBytes", P::Boolean},       {GL_PACK_LSB_FIRST, "PackLsbFirst", P::Boolean},
      {GL_PACK_ROW_LENGTH, "PackRowLength", P::Count},         {GL_PACK_IMAGE_HEIGHT, "PackImageHeight", P::Count},
      {GL_PACK_SKIP_ROWS, "PackSkipRows", P::Count},           {GL_PACK_SKIP_PIXELS, "PackSkipPixels", P::Count},
      {GL_PACK_SKIP_IMAGES, "PackSkipImages", P::Count},       {GL_PACK_ALIGNMENT, "PackAlignment", P::Alignment},
      {GL_UNPACK_SWAP_BYTES, "UnpackSwapBytes", P::Boolean},   {GL_UNPACK_LSB_FIRST, "UnpackLsbFirst", P::Boolean},
      {GL_UNPACK_ROW_LENGTH, "UnpackRowLength", P::Count},     {GL_UNPACK_IMAGE_HEIGHT, "UnpackImageHeight", P::Count},
      {GL_UNPACK_SKIP_ROWS, "UnpackSkipRows", P::Count},       {GL_UNPACK_SKIP_PIXELS, "UnpackSkipPixels", P::Count},
      {GL_UNPACK_SKIP_IMAGES, "UnpackSkipImages", P::Count},   {GL_UNPACK_ALIGNMENT, "UnpackAlignment", P::Alignment},
  };
  std::vector<Case> rows;
  for (const P& p : pnames)
    for (GLint value : {-1, 0, 3, 8}) {
      const bool valid = p.kind == P::Boolean || (p.kind == P::Count && value >= 0) ||
                         (p.kind == P::Alignment && (value == 1 || value == 2 || value == 4 || value == 8));
      const std::string v = value < 0 ? "Minus" + std::to_string(-value) : std::to_string(value);
      const GLenum pname = p.pname;
      rows.push_back({std::string("PixelStorei_") + p.name + v, nullptr, [pname, value] { glPixelStorei(pname, value); },
                      valid ? OK : IV});
    }
  return rows;
}
INSTANTIATE_TEST_SUITE_P(PixelStore, Errors, ::testing::ValuesIn(pixel_store_rows()), case_name);

}  // namespace
}  // namespace ffc::state_test
