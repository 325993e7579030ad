// Seed 000's "[Practice] OpenGL Lighting" scene around the cube (camera, axes, light, material and
// the interleaved cube array), shared by the cube examples so each file shows only its topic.
#pragma once
#include <string>

#include "gl/dispatch.h"

namespace lab {

// gCamAng and gCamHeight with the seed's key_callback: 1/3 turn the camera by -10/+10 degrees,
// 2/W raise/lower it by 0.1.
struct Camera {
  double ang = 0, height = 1;
  bool on_key(int key);  // true if the key was one of the camera's
  std::string describe() const;  // "0 deg, height 1.0", for window titles
};

void drawFrame();

// render() up to the object: clear, depth test, projection, gluLookAt, drawFrame (unlit), then
// lighting with light 0 at (3,4,5,1) placed after the camera, and the red material. Leaves
// GL_RESCALE_NORMAL on, as the seed does.
void beginRender(const Camera& cam);

// createVertexArraySeparate(): 36 vertices, each a normal then a position (6 floats).
extern const GLfloat gVertexArraySeparate[36 * 6];
void drawCube_glDrawArray();

}  // namespace lab
