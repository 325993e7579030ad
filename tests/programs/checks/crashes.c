/* Shows one frame, then dereferences a null pointer in its second display. */
#include <GL/glut.h>

static int frames;

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
    if (frames++ == 1)
        *(volatile int *) 0 = 1;
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(32, 32);
    glutCreateWindow("crashes");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
