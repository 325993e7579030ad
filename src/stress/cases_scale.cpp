// The stress catalogue's scale cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_scale(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    const std::string s = suffix(m);
    Case c;
    c.group = "scale";
    c.name = "scale_1e-6_" + s;
    c.draw = scaled_sphere({1e-6, 1e-6, 1e-6}, m);
    c.note = "glScalef(1e-6) under a rotation, the sphere's coordinates multiplied by 1e6. Normals "
             "transform by the inverse transpose (2.11.3): they come out 1e6 long. " +
             std::string(m == Normals::Normalize ? "GL_NORMALIZE brings them back to unit length: the picture is the unscaled sphere's."
                         : m == Normals::Rescale ? "GL_RESCALE_NORMAL divides by the length of M^-1's third row (1e6): exactly unit for a uniform scale, so this equals GL_NORMALIZE (the test compares them)."
                                                 : "Neither: n.L is 1e6 times too large and the diffuse and specular terms saturate where n.L > 0; the clamp to [0,1] (2.14.6) keeps the colours in range.");
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    const std::string s = suffix(m);
    Case c;
    c.group = "scale";
    c.name = "scale_1e6_" + s;
    c.draw = scaled_sphere({1e6, 1e6, 1e6}, m);
    c.note = "glScalef(1e6) under a rotation, coordinates multiplied by 1e-6: the normals come out 1e-6 long. " +
             std::string(m == Normals::Normalize ? "GL_NORMALIZE restores them."
                         : m == Normals::Rescale ? "GL_RESCALE_NORMAL multiplies by 1e6 (1 / the length of M^-1's third row)."
                                                 : "Neither: the diffuse and specular terms are a millionth of their size; only ambient and emission remain visible.");
    if (m == Normals::Rescale) {
      c.note += " Mesa computes the rescale factor from its float inverse as 1/sqrt(f), f = m[2]^2 + m[6]^2 + m[10]^2, "
                "but takes f = 1 when f < 1e-12 (state.c, update_modelview_scale): at a scale of 1e6, f is 1e-12 within float rounding.";
    }
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "scale_1e7_rescale";
    c.draw = scaled_sphere({1e7, 1e7, 1e7}, Normals::Rescale);
    c.note = "glScalef(1e7) under a rotation with GL_RESCALE_NORMAL: the spec's factor (2.11.3) is 1e7 and "
             "makes the 1e-7-long normals unit. Mesa takes f = 1 when f = m[2]^2 + m[6]^2 + m[10]^2 of its "
             "inverse is below 1e-12 (state.c, update_modelview_scale), here 1e-14: it does not rescale, "
             "the normals stay 1e-7 long and only ambient remains.";
    c.mesa = MesaExpectation::Deviation;
    c.mesa_reason = "Mesa skips GL_RESCALE_NORMAL when its factor's f is below 1e-12 (uniform scales above 1e6)";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_1e-30_") + suffix(m);
    c.draw = scaled_sphere({1e-30, 1e-30, 1e-30}, m);
    c.note = "glScalef(1e-30) under a rotation, coordinates multiplied by 1e30 (still finite in float). "
             "Well conditioned but with a determinant of 1e-90: the spec cannot specify behaviour for a "
             "poorly conditioned or nearly singular modelview (2.11.3)." + kMesaInverse +
             " Here the row's sum of squares, 1e-60, underflows float: Mesa calls the matrix singular and "
             "transforms normals by the identity, so they are not rotated with the sphere. Ours inverts in "
             "double (exactly 1e30 times the rotation).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "nearly singular modelview: Mesa's float inverse underflows and it uses the identity";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Plain}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_1e30_") + suffix(m);
    c.draw = scaled_sphere({1e30, 1e30, 1e30}, m);
    c.note = "glScalef(1e30) under a rotation, coordinates multiplied by 1e-30: beyond the 2^32 that "
             "floating-point values must reach (2.1.1), so unspecified." + kMesaInverse +
             " Here the row's sum of squares, 1e60, overflows float to infinity and Mesa's inverse is 1/inf = 0: "
             "every normal becomes zero" +
             std::string(m == Normals::Normalize ? " (GL_NORMALIZE then makes NaN, which Mesa's lighting drops: ambient only)"
                                                 : ", and ours are 1e-30 long: ambient only on both") +
             ". Ours inverts in double.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "beyond float range: Mesa's float inverse overflows to a zero normal matrix";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale, Normals::Plain}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_0_z_") + suffix(m);
    c.draw = scaled_sphere({1, 1, 0}, m);
    c.note = "glScalef(1, 1, 0) under a rotation flattens the sphere: the modelview is singular. 2.11.3: "
             "'In case of an exactly singular matrix, the transformed normal is undefined. If the GL "
             "implementation determines that the model-view matrix is uninvertible, then the entries in the "
             "inverted matrix are arbitrary.' It must not interrupt the GL." + kMesaInverse +
             " Here the determinant is exactly 0 and Mesa uses the identity; so does ours (a singular "
             "modelview, see modelview_singular_rank2, gives the identity). Back faces are culled: the "
             "flattened sphere's front and back share one depth.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "singular modelview: the transformed normal is undefined";
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "scale_0_all_normalize";
    c.draw = scaled_sphere({0, 0, 0}, Normals::Normalize);
    c.note = "glScalef(0, 0, 0): every vertex lands on one point and every normal is undefined (2.11.3). "
             "The triangles have no area: nothing is drawn, but feedback reports each one (feedback is "
             "after clipping, before rasterization; culling is off), with the colour the identity normal "
             "matrix gives (Mesa's choice for a singular modelview, and ours).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "singular modelview: the transformed normal is undefined";
    add(c);
  }
  for (Normals m : {Normals::Normalize, Normals::Rescale}) {
    Case c;
    c.group = "scale";
    c.name = std::string("scale_nonuniform_1e-6_") + suffix(m);
    c.draw = scaled_sphere({1e-6, 1, 1}, m);
    c.note = "glScalef(1e-6, 1, 1) under a rotation, x coordinates multiplied by 1e6: non-singular "
             "(det 1e-6), so the inverse transpose is defined and Mesa's adjugate inverse takes it. " +
             std::string(m == Normals::Normalize ? "GL_NORMALIZE: the picture is the unscaled sphere's."
                                                 : "GL_RESCALE_NORMAL's factor is defined for any matrix (2.11.3) but makes unit normals only for a uniform scale: the normals here are up to 1e6 long and the lighting saturates.");
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "modelview_singular_rank2";
    c.draw = [] {
      scenes::standard();
      glEnable(GL_NORMALIZE);
      glTranslatef(0, 0, -4);
      // I - n n^T with n = (1, 1, 1)/sqrt(3): the projection onto a tilted plane, rank 2.
      const double t = 1.0 / 3;
      const GLdouble mtx[16] = {1 - t, -t, -t, 0, -t, 1 - t, -t, 0, -t, -t, 1 - t, 0, 0, 0, 0, 1};
      glMultMatrixd(mtx);
      glEnable(GL_CULL_FACE);  // the flattened sphere's front and back lie at one depth
      scenes::draw(scenes::sphere(3));
    };
    c.note = "A rank-2 modelview (the projection onto the plane through the origin normal to (1,1,1), as "
             "a planar-shadow matrix is): singular, so the transformed normal is undefined (2.11.3) and may "
             "be anything but must not stop the GL. Rounding hides the singularity: Mesa's float "
             "determinant is exactly 0 and it uses the identity; ours, in double, gets 8e-17, whose "
             "inverse would be rounding noise times 1e16, so ours calls a matrix singular when |det| is "
             "below 1e-14 of the Hadamard bound (the product of its row or column lengths) and uses the "
             "identity too. Back faces are culled (front and back of the flattened sphere share a depth).";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "singular modelview: the transformed normal is undefined";
    add(c);
  }
  {
    Case c;
    c.group = "scale";
    c.name = "modelview_near_singular";
    c.draw = scaled_sphere({1e-13, 1e-13, 1}, Normals::Normalize);
    c.note = "glRotatef(30, 1, 1, 0) then glScalef(1e-13, 1e-13, 1), coordinates multiplied back: "
             "determinant 1e-26, perfectly invertible in double. The spec does not specify poorly "
             "conditioned or nearly singular modelviews (2.11.3)." + kMesaInverse +
             " With |det| < 1e-25 Mesa calls it singular and uses the identity: its normals are not "
             "rotated; ours are.";
    c.mesa = MesaExpectation::Undefined;
    c.mesa_reason = "nearly singular modelview: Mesa refuses |det| < 1e-25 and uses the identity";
    add(c);
  }
}

}  // namespace ffc::stress::kit
