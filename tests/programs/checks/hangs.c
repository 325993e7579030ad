/* Never returns from its first display callback. */
#include <GL/glut.h>

static void display(void)
{
    volatile int forever = 1;
    glClear(GL_COLOR_BUFFER_BIT);
    while (forever)
        ;
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(32, 32);
    glutCreateWindow("hangs");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
