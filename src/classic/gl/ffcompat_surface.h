/* The C face of ffcompat's libGL.so.1 for window-system glue (our GLUT): a drawing surface on one
 * of ffcompat's backends, made current for the plain gl* entry points the library exports.
 *
 *   ffcompat_surface* s = ffcompat_surface_create(640, 480);  // backend: $FFCOMPAT_BACKEND, soft
 *   ... gl* calls ...
 *   ffcompat_surface_read_rgba(s, pixels);                     // finishes drawing first
 */
#ifndef FFCOMPAT_SURFACE_H
#define FFCOMPAT_SURFACE_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct ffcompat_surface ffcompat_surface;

/* Makes a width x height surface (RGBA8, 24-bit depth) in GL's default state on the backend named
 * by the environment variable FFCOMPAT_BACKEND ("soft" when unset; "mesa"; "glsl"; the other names of
 * `ffcompat backends`) and makes it current. NULL on failure, with one line on stderr saying why. */
ffcompat_surface* ffcompat_surface_create(int width, int height);
/* Makes the surface current again, with its state and contents (on this thread); NULL: none. */
void ffcompat_surface_make_current(ffcompat_surface* s);
/* Finishes drawing; writes width * height * 4 bytes, RGBA, the top row first. */
void ffcompat_surface_read_rgba(ffcompat_surface* s, unsigned char* out);
/* Gives the surface a new width x height framebuffer (a window resized), keeping its GL state,
 * the viewport included; the new buffer's contents are undefined until cleared. 0 on success; -1
 * for a size outside 1..16384 or a NULL surface, the surface unchanged. Which surface is current
 * does not change. */
int ffcompat_surface_resize(ffcompat_surface* s, int width, int height);
int ffcompat_surface_width(const ffcompat_surface* s);
int ffcompat_surface_height(const ffcompat_surface* s);
/* The backend's name ("soft", "mesa", ...). */
const char* ffcompat_surface_backend(const ffcompat_surface* s);
/* Finishes the surface's drawing and frees it; the current surface, destroyed, leaves none current. */
void ffcompat_surface_destroy(ffcompat_surface* s);

/* The address of this library's export of a gl* function of <GL/gl.h> ("glBegin"), whichever
 * backend is current (each call goes to the current surface's); NULL for any other name. */
void* ffcompat_get_proc_address(const char* name);

#ifdef __cplusplus
}
#endif
#endif
