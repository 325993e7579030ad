/* Points and lines of several sizes: rows of points from 1 to 6 pixels, lines from 1 to 5 pixels
 * wide at several slopes, a lit line loop, and a stippled line. The up and down arrow keys add
 * or take away a pixel from every size; F1 toggles smooth shading of the lines' colours. */
#include <GL/glut.h>

static int extra;
static int smooth = 1;

static void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);

    for (i = 0; i < 6; i++) {
        glPointSize((GLfloat) (1 + i + extra));
        glBegin(GL_POINTS);
        glColor3f(1.0f, 0.2f * i, 0.0f);
        glVertex2f(15.0f + 30.0f * i, 180.0f);
        glColor3f(0.0f, 1.0f, 0.2f * i);
        glVertex2f(15.5f + 30.0f * i, 165.5f);
        glEnd();
    }

    for (i = 0; i < 5; i++) {
        glLineWidth((GLfloat) (1 + i + extra));
        glBegin(GL_LINES);
        glColor3f(1.0f, 1.0f, 1.0f);
        glVertex2f(10.0f + 38.0f * i, 150.0f);
        glColor3f(0.2f, 0.4f, 1.0f);
        glVertex2f(40.0f + 38.0f * i, 100.0f + 10.0f * i);
        glEnd();
    }

    glLineWidth(1.0f + extra);
    glBegin(GL_LINE_LOOP);
    glColor3f(1.0f, 0.0f, 0.0f); glVertex2f(20.0f, 20.0f);
    glColor3f(0.0f, 1.0f, 0.0f); glVertex2f(90.0f, 30.0f);
    glColor3f(0.0f, 0.0f, 1.0f); glVertex2f(70.0f, 85.0f);
    glEnd();

    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0F0F);
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(110.0f, 20.0f);
    glVertex2f(190.0f, 50.0f);
    glVertex2f(120.0f, 85.0f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glFlush();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 200.0, 0.0, 200.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void special(int key, int x, int y)
{
    (void) x; (void) y;
    if (key == GLUT_KEY_UP)
        extra++;
    else if (key == GLUT_KEY_DOWN && extra > 0)
        extra--;
    else if (key == GLUT_KEY_F1)
        smooth = !smooth;
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(200, 200);
    glutCreateWindow("points and lines");
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutSpecialFunc(special);
    glutMainLoop();
    return 0;
}
