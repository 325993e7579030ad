/* Prints every callback GLUT makes, with the values a program can see (modifiers, pointer
 * positions, GLUT_ELAPSED_TIME), so that a scripted run can be checked line by line. */
#include <GL/freeglut.h>
#include <stdio.h>

static int frames;

static void display(void)
{
    printf("display %d at %d ms: %dx%d at %d,%d\n", frames++, glutGet(GLUT_ELAPSED_TIME),
           glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y));
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
}

static void reshape(int w, int h) { printf("reshape %d %d\n", w, h); glViewport(0, 0, w, h); }
static void position(int x, int y) { printf("position %d %d\n", x, y); }
static void visibility(int state) { printf("visibility %d\n", state); }
static void timer(int value) { printf("timer %d at %d ms\n", value, glutGet(GLUT_ELAPSED_TIME)); }

static void keyboard(unsigned char key, int x, int y)
{
    printf("key %d modifiers %d at %d,%d\n", key, glutGetModifiers(), x, y);
    glutPostRedisplay();
}
static void keyboard_up(unsigned char key, int x, int y) { printf("key up %d at %d,%d\n", key, x, y); }
static void special(int key, int x, int y)
{
    printf("special %d modifiers %d at %d,%d\n", key, glutGetModifiers(), x, y);
    glutPostRedisplay();
}
static void special_up(int key, int x, int y) { printf("special up %d at %d,%d\n", key, x, y); }
static void mouse(int button, int state, int x, int y)
{
    printf("mouse %d %s at %d,%d\n", button, state == GLUT_DOWN ? "down" : "up", x, y);
    glutPostRedisplay();
}
static void motion(int x, int y) { printf("motion %d,%d\n", x, y); }
static void passive(int x, int y) { printf("passive %d,%d\n", x, y); glutPostRedisplay(); }

int main(int argc, char **argv)
{
    int i;
    glutInit(&argc, argv);
    printf("%d arguments left:", argc);
    for (i = 1; i < argc; i++)
        printf(" %s", argv[i]);
    printf("\ninit window %d,%d %dx%d\n", glutGet(GLUT_INIT_WINDOW_X), glutGet(GLUT_INIT_WINDOW_Y),
           glutGet(GLUT_INIT_WINDOW_WIDTH), glutGet(GLUT_INIT_WINDOW_HEIGHT));
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    printf("window %d\n", glutCreateWindow("callbacks"));
    printf("double %d depth %d\n", glutGet(GLUT_WINDOW_DOUBLEBUFFER), glutGet(GLUT_WINDOW_DEPTH_SIZE));
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutPositionFunc(position);
    glutVisibilityFunc(visibility);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(keyboard_up);
    glutSpecialFunc(special);
    glutSpecialUpFunc(special_up);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutPassiveMotionFunc(passive);
    glutTimerFunc(50, timer, 2);
    glutTimerFunc(0, timer, 1);
    glutMainLoop();
    return 0;
}
