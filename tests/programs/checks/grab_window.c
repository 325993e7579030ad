/* grab_window OUT.png TITLE: waits (up to 20 s) for a mapped window of that title on $DISPLAY,
 * gives it a second to draw, and writes what it shows as an RGB PNG. For comparing a program run
 * on the system's freeglut and GLX with the same program run on ffcompat. */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static Window find(Display *d, Window w, const char *title)
{
    char *name = NULL;
    Window root, parent, *kids = NULL, found = 0;
    unsigned count, i;
    if (XFetchName(d, w, &name) && name) {
        XWindowAttributes a;
        int same = strcmp(name, title) == 0;
        XFree(name);
        if (same && XGetWindowAttributes(d, w, &a) && a.map_state == IsViewable && a.class == InputOutput)
            return w;
    }
    if (!XQueryTree(d, w, &root, &parent, &kids, &count))
        return 0;
    for (i = 0; i < count && !found; i++)
        found = find(d, kids[i], title);
    if (kids)
        XFree(kids);
    return found;
}

int main(int argc, char **argv)
{
    Display *d;
    Window w = 0;
    XWindowAttributes a;
    XImage *image;
    png_image png;
    unsigned char *rgb;
    int tries, x, y;

    if (argc != 3) {
        fprintf(stderr, "usage: grab_window OUT.png TITLE\n");
        return 2;
    }
    d = XOpenDisplay(NULL);
    if (!d) {
        fprintf(stderr, "grab_window: no X display\n");
        return 1;
    }
    for (tries = 0; tries < 200 && !w; tries++) {
        w = find(d, DefaultRootWindow(d), argv[2]);
        if (!w)
            usleep(100000);
    }
    if (!w) {
        fprintf(stderr, "grab_window: no window titled '%s'\n", argv[2]);
        return 1;
    }
    sleep(1);
    XGetWindowAttributes(d, w, &a);
    image = XGetImage(d, w, 0, 0, (unsigned) a.width, (unsigned) a.height, AllPlanes, ZPixmap);
    rgb = malloc((size_t) a.width * a.height * 3);
    for (y = 0; y < a.height; y++)
        for (x = 0; x < a.width; x++) {
            unsigned long p = XGetPixel(image, x, y);
            unsigned char *out = rgb + ((size_t) y * a.width + x) * 3;
            out[0] = (unsigned char) ((p & image->red_mask) >> 16);
            out[1] = (unsigned char) ((p & image->green_mask) >> 8);
            out[2] = (unsigned char) (p & image->blue_mask);
        }
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = (png_uint_32) a.width;
    png.height = (png_uint_32) a.height;
    png.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&png, argv[1], 0, rgb, 0, NULL)) {
        fprintf(stderr, "grab_window: cannot write %s\n", argv[1]);
        return 1;
    }
    return 0;
}
