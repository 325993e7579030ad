// The rest of freeglut 3.4's exports: devices, overlays, game mode, colour maps and video resizing
// that a headless or GLFW window does not have. Each exists with freeglut's prototype, does
// nothing, returns "none" (0 or NULL), and names itself once on stderr with the reason.
#include "glut_state.h"

using namespace ffc::glut;

extern "C" {

void glutButtonBoxFunc(void (*)(int, int)) {
  say_once("glutButtonBoxFunc", "there is no button box");
}

void glutButtonBoxFuncUcall(void (*)(int, int, void*), void*) {
  say_once("glutButtonBoxFuncUcall", "there is no button box");
}

void glutCopyColormap(int) {
  say_once("glutCopyColormap", "windows are RGBA, with no colour index map");
}

void glutDialsFunc(void (*)(int, int)) {
  say_once("glutDialsFunc", "there is no dial box");
}

void glutDialsFuncUcall(void (*)(int, int, void*), void*) {
  say_once("glutDialsFuncUcall", "there is no dial box");
}

int glutEnterGameMode(void) {
  say_once("glutEnterGameMode", "there is no game mode (the window keeps its size)");
  return 0;
}

void glutEstablishOverlay(void) {
  say_once("glutEstablishOverlay", "there are no overlays");
}

void glutForceJoystickFunc(void) {
  say_once("glutForceJoystickFunc", "there is no joystick");
}

int glutGameModeGet(GLenum) {
  say_once("glutGameModeGet", "there is no game mode (the window keeps its size)");
  return 0;
}

void glutGameModeString(const char*) {
  say_once("glutGameModeString", "there is no game mode (the window keeps its size)");
}

GLfloat glutGetColor(int, int) {
  say_once("glutGetColor", "windows are RGBA, with no colour index map");
  return 0.0f;
}

int * glutGetModeValues(GLenum, int *) {
  say_once("glutGetModeValues", "there are no multisample modes");
  return nullptr;
}

void glutHideOverlay(void) {
  say_once("glutHideOverlay", "there are no overlays");
}

void glutJoystickFunc(void (*)(unsigned int, int, int, int), int) {
  say_once("glutJoystickFunc", "there is no joystick");
}

void glutJoystickFuncUcall(void (*)(unsigned int, int, int, int, void*), int, void*) {
  say_once("glutJoystickFuncUcall", "there is no joystick");
}

void glutLeaveGameMode(void) {
  say_once("glutLeaveGameMode", "there is no game mode (the window keeps its size)");
}

void glutMultiButtonFunc(void (*)(int, int, int, int, int)) {
  say_once("glutMultiButtonFunc", "there is one pointer only");
}

void glutMultiButtonFuncUcall(void (*)(int, int, int, int, int, void*), void*) {
  say_once("glutMultiButtonFuncUcall", "there is one pointer only");
}

void glutMultiEntryFunc(void (*)(int, int)) {
  say_once("glutMultiEntryFunc", "there is one pointer only");
}

void glutMultiEntryFuncUcall(void (*)(int, int, void*), void*) {
  say_once("glutMultiEntryFuncUcall", "there is one pointer only");
}

void glutMultiMotionFunc(void (*)(int, int, int)) {
  say_once("glutMultiMotionFunc", "there is one pointer only");
}

void glutMultiMotionFuncUcall(void (*)(int, int, int, void*), void*) {
  say_once("glutMultiMotionFuncUcall", "there is one pointer only");
}

void glutMultiPassiveFunc(void (*)(int, int, int)) {
  say_once("glutMultiPassiveFunc", "there is one pointer only");
}

void glutMultiPassiveFuncUcall(void (*)(int, int, int, void*), void*) {
  say_once("glutMultiPassiveFuncUcall", "there is one pointer only");
}

void glutPostOverlayRedisplay(void) {
  say_once("glutPostOverlayRedisplay", "there are no overlays");
}

void glutPostWindowOverlayRedisplay(int) {
  say_once("glutPostWindowOverlayRedisplay", "there are no overlays");
}

void glutRemoveOverlay(void) {
  say_once("glutRemoveOverlay", "there are no overlays");
}


void glutSetColor(int, GLfloat, GLfloat, GLfloat) {
  say_once("glutSetColor", "windows are RGBA, with no colour index map");
}

void glutSetVertexAttribCoord3(GLint) {
  say_once("glutSetVertexAttribCoord3", "the shapes draw with the fixed-function pipeline");
}

void glutSetVertexAttribNormal(GLint) {
  say_once("glutSetVertexAttribNormal", "the shapes draw with the fixed-function pipeline");
}

void glutSetVertexAttribTexCoord2(GLint) {
  say_once("glutSetVertexAttribTexCoord2", "the shapes draw with the fixed-function pipeline");
}

void glutSetupVideoResizing(void) {
  say_once("glutSetupVideoResizing", "the screen is not resized");
}

void glutShowOverlay(void) {
  say_once("glutShowOverlay", "there are no overlays");
}

void glutSpaceballButtonFunc(void (*)(int, int)) {
  say_once("glutSpaceballButtonFunc", "there is no spaceball");
}

void glutSpaceballButtonFuncUcall(void (*)(int, int, void*), void*) {
  say_once("glutSpaceballButtonFuncUcall", "there is no spaceball");
}

void glutSpaceballMotionFunc(void (*)(int, int, int)) {
  say_once("glutSpaceballMotionFunc", "there is no spaceball");
}

void glutSpaceballMotionFuncUcall(void (*)(int, int, int, void*), void*) {
  say_once("glutSpaceballMotionFuncUcall", "there is no spaceball");
}

void glutSpaceballRotateFunc(void (*)(int, int, int)) {
  say_once("glutSpaceballRotateFunc", "there is no spaceball");
}

void glutSpaceballRotateFuncUcall(void (*)(int, int, int, void*), void*) {
  say_once("glutSpaceballRotateFuncUcall", "there is no spaceball");
}

void glutStopVideoResizing(void) {
  say_once("glutStopVideoResizing", "the screen is not resized");
}

void glutTabletButtonFunc(void (*)(int, int, int, int)) {
  say_once("glutTabletButtonFunc", "there is no tablet");
}

void glutTabletButtonFuncUcall(void (*)(int, int, int, int, void*), void*) {
  say_once("glutTabletButtonFuncUcall", "there is no tablet");
}

void glutTabletMotionFunc(void (*)(int, int)) {
  say_once("glutTabletMotionFunc", "there is no tablet");
}

void glutTabletMotionFuncUcall(void (*)(int, int, void*), void*) {
  say_once("glutTabletMotionFuncUcall", "there is no tablet");
}

void glutUseLayer(GLenum) {
  say_once("glutUseLayer", "there are no overlays");
}

void glutVideoPan(int, int, int, int) {
  say_once("glutVideoPan", "the screen is not resized");
}

void glutVideoResize(int, int, int, int) {
  say_once("glutVideoResize", "the screen is not resized");
}

int glutVideoResizeGet(GLenum) {
  say_once("glutVideoResizeGet", "the screen is not resized");
  return 0;
}

// Declared by no public header of freeglut 3.4 but exported by it (fg_joystick.c's prototypes).
int glutJoystickGetNumAxes(int ident);
int glutJoystickGetNumButtons(int ident);
int glutJoystickNotWorking(int ident);
float glutJoystickGetDeadBand(int ident, int axis);
void glutJoystickSetDeadBand(int ident, int axis, float db);
float glutJoystickGetSaturation(int ident, int axis);
void glutJoystickSetSaturation(int ident, int axis, float st);
void glutJoystickSetMinRange(int ident, float* axes);
void glutJoystickSetMaxRange(int ident, float* axes);
void glutJoystickSetCenter(int ident, float* axes);
void glutJoystickGetMinRange(int ident, float* axes);
void glutJoystickGetMaxRange(int ident, float* axes);
void glutJoystickGetCenter(int ident, float* axes);

int glutJoystickGetNumAxes(int) {
  say_once("glutJoystickGetNumAxes", "there is no joystick");
  return 0;
}
int glutJoystickGetNumButtons(int) {
  say_once("glutJoystickGetNumButtons", "there is no joystick");
  return 0;
}
// Always "not working": there is none.
int glutJoystickNotWorking(int) {
  say_once("glutJoystickNotWorking", "there is no joystick");
  return 1;
}
float glutJoystickGetDeadBand(int, int) {
  say_once("glutJoystickGetDeadBand", "there is no joystick");
  return 0.0f;
}
void glutJoystickSetDeadBand(int, int, float) {
  say_once("glutJoystickSetDeadBand", "there is no joystick");
}
float glutJoystickGetSaturation(int, int) {
  say_once("glutJoystickGetSaturation", "there is no joystick");
  return 0.0f;
}
void glutJoystickSetSaturation(int, int, float) {
  say_once("glutJoystickSetSaturation", "there is no joystick");
}
void glutJoystickSetMinRange(int, float*) {
  say_once("glutJoystickSetMinRange", "there is no joystick");
}
void glutJoystickSetMaxRange(int, float*) {
  say_once("glutJoystickSetMaxRange", "there is no joystick");
}
void glutJoystickSetCenter(int, float*) {
  say_once("glutJoystickSetCenter", "there is no joystick");
}
void glutJoystickGetMinRange(int, float*) {
  say_once("glutJoystickGetMinRange", "there is no joystick");
}
void glutJoystickGetMaxRange(int, float*) {
  say_once("glutJoystickGetMaxRange", "there is no joystick");
}
void glutJoystickGetCenter(int, float*) {
  say_once("glutJoystickGetCenter", "there is no joystick");
}

// Real: the GL errors of the current window's context, one line each, as freeglut prints them.
void glutReportErrors(void) {
  static const struct { GLenum code; const char* text; } names[] = {
      {GL_INVALID_ENUM, "invalid enumerant"}, {GL_INVALID_VALUE, "invalid value"},
      {GL_INVALID_OPERATION, "invalid operation"}, {GL_STACK_OVERFLOW, "stack overflow"},
      {GL_STACK_UNDERFLOW, "stack underflow"}, {GL_OUT_OF_MEMORY, "out of memory"}};
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    const char* text = "unknown error";
    for (const auto& n : names)
      if (n.code == e) text = n.text;
    warning("GL error: %s", text);
  }
}

}  // extern "C"
