// libOpenGL.so.0: GLVND's name for the GL functions, which CMake's FindOpenGL links for OpenGL::GL
// by default (policy CMP0072), with libGLX.so.0 beside it. A classic program built so would never
// load libGL.so.1; this library has no code and exports nothing, and only needs libGL.so.1, so
// the program's gl* names are found in ffcompat's libGL.so.1 when build/classic is first on its
// library path.
