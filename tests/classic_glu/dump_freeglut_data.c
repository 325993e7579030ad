/* Regenerates src/classic/glut/font_data.cpp and teapot_data.h from the system's freeglut 3.4.0
 * (libglut.so.3.12): the glyphs of its bitmap and stroke fonts (exported as fgFont* / fgStroke*) and
 * the teapot, teacup and teaspoon control points (static arrays, found in the library's bytes by
 * their known first values). Data, not code: run by hand when the data must be checked again,
 *   cc -o dump tests/classic_glu/dump_freeglut_data.c -ldl && ./dump font && ./dump teapot
 * and compare with the body of namespace ffc::glut in font_data.cpp and teapot_data.h (the latter
 * with its arrays marked inline). The struct layouts below are freeglut's (fg_internal.h), as sized by `nm -S` (32 and 24 bytes). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef unsigned char GLubyte;
struct bitmap_font { const char *name; int quantity; int height; const GLubyte **characters; float xorig, yorig; };
struct stroke_vertex { float x, y; };
struct stroke_strip { int number; const struct stroke_vertex *vertices; };
struct stroke_char { float right; int number; const struct stroke_strip *strips; };
struct stroke_font { const char *name; int quantity; float height; const struct stroke_char **characters; };

static void dump_bitmap(void *lib, const char *symbol, const char *id) {
  const struct bitmap_font *f = dlsym(lib, symbol);
  if (!f) { fprintf(stderr, "no %s\n", symbol); exit(1); }
  int offsets[256], at = 0;
  printf("// %s: %s\nconst GLubyte k%sGlyphs[] = {", symbol, f->name, id);
  for (int c = 0; c < 256; ++c) {
    const GLubyte *g = c < f->quantity ? f->characters[c] : NULL;
    offsets[c] = at;
    const int width = g ? g[0] : 0;
    const int bytes = 1 + f->height * ((width + 7) / 8);
    for (int i = 0; i < bytes; ++i, ++at) printf("%s0x%02x,", at % 16 ? "" : "\n  ", g ? g[i] : 0);
  }
  printf("\n};\nconst unsigned short k%sOffsets[256] = {", id);
  for (int c = 0; c < 256; ++c) printf("%s%d,", c % 16 ? " " : "\n  ", offsets[c]);
  printf("\n};\nconst BitmapFont k%s = {%d, %a, %a, k%sGlyphs, k%sOffsets};\n\n", id, f->height, f->xorig, f->yorig, id, id);
}

static void dump_stroke(void *lib, const char *symbol, const char *id) {
  const struct stroke_font *f = dlsym(lib, symbol);
  if (!f) { fprintf(stderr, "no %s\n", symbol); exit(1); }
  printf("// %s: %s\nconst StrokeVertex k%sVertices[] = {", symbol, f->name, id);
  int n = 0;
  for (int c = 0; c < f->quantity; ++c) {
    const struct stroke_char *ch = f->characters[c];
    for (int s = 0; ch && s < ch->number; ++s)
      for (int v = 0; v < ch->strips[s].number; ++v, ++n)
        printf("%s{%a, %a},", n % 4 ? " " : "\n  ", ch->strips[s].vertices[v].x, ch->strips[s].vertices[v].y);
  }
  printf("\n};\nconst StrokeStrip k%sStrips[] = {", id);
  int first = 0, strips = 0;
  for (int c = 0; c < f->quantity; ++c) {
    const struct stroke_char *ch = f->characters[c];
    for (int s = 0; ch && s < ch->number; ++s, ++strips) {
      printf("%s{%d, %d},", strips % 8 ? " " : "\n  ", ch->strips[s].number, first);
      first += ch->strips[s].number;
    }
  }
  printf("\n};\nconst StrokeChar k%sChars[] = {", id);
  int first_strip = 0;
  for (int c = 0; c < f->quantity; ++c) {
    const struct stroke_char *ch = f->characters[c];
    /* A missing character (none in 3.4.0's fonts, but allowed) has strip count -1. */
    printf("\n  {%a, %d, %d},", ch ? ch->right : 0.0f, ch ? ch->number : -1, first_strip);
    if (ch) first_strip += ch->number;
  }
  printf("\n};\nconst StrokeFont k%s = {%d, %a, k%sChars, k%sStrips, k%sVertices};\n\n", id, f->quantity, f->height,
         id, id, id);
}

static unsigned char *image;
static long image_size;

static const void *find(const void *pattern, size_t bytes) {
  for (long i = 0; i + (long)bytes <= image_size; i += 4)
    if (memcmp(image + i, pattern, bytes) == 0) return image + i;
  fprintf(stderr, "pattern not found\n");
  exit(1);
}

static void dump_floats(const char *name, const float *first3, int points) {
  const float *p = find(first3, 3 * sizeof(float));
  printf("const GLfloat %s[%d][3] = {", name, points);
  for (int i = 0; i < points; ++i) printf("%s{%a, %a, %a},", i % 2 ? " " : "\n    ", p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  printf("\n};\n");
}

static void dump_patches(const char *name, const int *prefix, int prefix_count, int patches) {
  const int *p = find(prefix, prefix_count * sizeof(int));
  printf("const int %s[%d][16] = {", name, patches);
  for (int i = 0; i < patches; ++i) {
    printf("\n    {");
    for (int j = 0; j < 16; ++j) printf("%d%s", p[16 * i + j], j < 15 ? ", " : "},");
  }
  printf("\n};\n");
}

int main(int argc, char **argv) {
  const char *what = argc > 1 ? argv[1] : "";
  void *lib = dlopen("libglut.so.3.12", RTLD_NOW);
  if (!lib) { fprintf(stderr, "%s\n", dlerror()); return 1; }
  if (strcmp(what, "font") == 0) {
    dump_bitmap(lib, "fgFontFixed8x13", "Fixed8x13");
    dump_bitmap(lib, "fgFontFixed9x15", "Fixed9x15");
    dump_bitmap(lib, "fgFontHelvetica10", "Helvetica10");
    dump_bitmap(lib, "fgFontHelvetica12", "Helvetica12");
    dump_bitmap(lib, "fgFontHelvetica18", "Helvetica18");
    dump_bitmap(lib, "fgFontTimesRoman10", "TimesRoman10");
    dump_bitmap(lib, "fgFontTimesRoman24", "TimesRoman24");
    dump_stroke(lib, "fgStrokeRoman", "StrokeRoman");
    dump_stroke(lib, "fgStrokeMonoRoman", "StrokeMonoRoman");
    return 0;
  }
  if (strcmp(what, "teapot") == 0) {
    Dl_info info;
    if (!dladdr(dlsym(lib, "glutSolidTeapot"), &info)) return 1;
    FILE *f = fopen(info.dli_fname, "rb");
    if (!f) return 1;
    fseek(f, 0, SEEK_END);
    image_size = ftell(f);
    fseek(f, 0, SEEK_SET);
    image = malloc(image_size);
    if (fread(image, 1, image_size, f) != (size_t)image_size) return 1;
    fclose(f);
    static const float teapot[3] = {1.4f, 0.0f, 2.4f}, teacup[3] = {1.44205f, 0.0f, 2.72386f},
                       teaspoon[3] = {-0.37768f, 0.0f, -0.06295f};
    int teapot_patch[48], teacup_patch[48], teaspoon_patch[32];
    for (int i = 0; i < 16; ++i) teapot_patch[i] = teacup_patch[i] = i, teapot_patch[16 + i] = teacup_patch[16 + i] = 12 + i;
    for (int i = 0; i < 16; ++i) teapot_patch[32 + i] = 24 + i;
    for (int i = 0; i < 12; ++i) teacup_patch[32 + i] = 28 + i;
    for (int i = 0; i < 4; ++i) teacup_patch[44 + i] = i;
    static const int spoon[32] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 13, 12,
                                  3, 14, 15, 16, 7, 17, 18, 19, 11, 20, 21, 22, 12, 23, 24, 25};
    memcpy(teaspoon_patch, spoon, sizeof spoon);
    dump_patches("kTeapotPatches", teapot_patch, 48, 10);
    dump_floats("kTeapotPoints", teapot, 129);
    dump_patches("kTeacupPatches", teacup_patch, 48, 7);
    dump_floats("kTeacupPoints", teacup, 92);
    dump_patches("kTeaspoonPatches", teaspoon_patch, 32, 16);
    dump_floats("kTeaspoonPoints", teaspoon, 144);
    return 0;
  }
  fprintf(stderr, "usage: %s font|teapot\n", argv[0]);
  return 2;
}
