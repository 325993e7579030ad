/* Drives GLUT with its own loop of glutMainLoopEvent, redrawing from a 100 ms timer, and prints
 * when each frame and each timer comes. */
#include <GL/freeglut.h>
#include <stdio.h>

static int frames;

static void display(void)
{
    printf("display %d at %d ms\n", frames++, glutGet(GLUT_ELAPSED_TIME));
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
}

static void tick(int value)
{
    printf("timer %d at %d ms\n", value, glutGet(GLUT_ELAPSED_TIME));
    glutPostRedisplay();
    glutTimerFunc(100, tick, value + 1);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(32, 32);
    glutCreateWindow("loop event");
    glutDisplayFunc(display);
    glutTimerFunc(100, tick, 1);
    for (;;)
        glutMainLoopEvent();
    return 0;
}
