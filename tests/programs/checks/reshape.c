/* Resizes its window from the keyboard: 'r' asks for 60x30, 'f' for the full screen; prints the
 * reshape callbacks and the size each frame is drawn at. */
#include <GL/freeglut.h>
#include <stdio.h>

static int frames;

static void display(void)
{
    printf("display %d at %d ms: %dx%d\n", frames++, glutGet(GLUT_ELAPSED_TIME), glutGet(GLUT_WINDOW_WIDTH),
           glutGet(GLUT_WINDOW_HEIGHT));
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
}

static void reshape(int w, int h) { printf("reshape %d %d\n", w, h); glViewport(0, 0, w, h); }

static void keyboard(unsigned char key, int x, int y)
{
    (void) x; (void) y;
    printf("key %c\n", key);
    if (key == 'r')
        glutReshapeWindow(60, 30);
    else if (key == 'f')
        glutFullScreen();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(40, 30);
    glutCreateWindow("reshape");
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
