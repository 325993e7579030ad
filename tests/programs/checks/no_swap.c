/* Double-buffered, but its display callback never calls glutSwapBuffers: nothing is ever shown. */
#include <GL/glut.h>

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(32, 32);
    glutCreateWindow("no swap");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
