/* A light moved with the mouse: dragging with the left button turns the light around the
 * object (x: around the vertical axis, y: up and down); a small yellow cube shows where it is.
 * The passive motion callback only counts moves; the middle button resets the light. */
#include <GL/glut.h>
#include <stdio.h>

static int spin_x = 30, spin_y = 20;
static int last_x, last_y, dragging;
static int passive_moves;

static void init(void)
{
    GLfloat grey[] = { 0.7f, 0.7f, 0.75f, 1.0f };
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glShadeModel(GL_SMOOTH);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, grey);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
}

static void display(void)
{
    GLfloat position[] = { 0.0f, 0.0f, 1.5f, 1.0f };

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    gluLookAt(0.0, 0.0, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

    glPushMatrix();
    glRotated((GLdouble) spin_x, 0.0, 1.0, 0.0);
    glRotated((GLdouble) spin_y, 1.0, 0.0, 0.0);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glTranslated(0.0, 0.0, 1.5);
    glDisable(GL_LIGHTING);
    glColor3f(1.0f, 1.0f, 0.0f);
    glutWireCube(0.1);
    glEnable(GL_LIGHTING);
    glPopMatrix();

    glutSolidTorus(0.275, 0.85, 16, 24);
    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (GLfloat) w / (GLfloat) h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void mouse(int button, int state, int x, int y)
{
    if (button == GLUT_LEFT_BUTTON) {
        dragging = state == GLUT_DOWN;
        last_x = x;
        last_y = y;
    } else if (button == GLUT_MIDDLE_BUTTON && state == GLUT_DOWN) {
        spin_x = 30;
        spin_y = 20;
        glutPostRedisplay();
    }
}

static void motion(int x, int y)
{
    if (!dragging)
        return;
    spin_x = (spin_x + (x - last_x)) % 360;
    spin_y = (spin_y + (y - last_y)) % 360;
    last_x = x;
    last_y = y;
    glutPostRedisplay();
}

static void passive(int x, int y)
{
    (void) x; (void) y;
    passive_moves++;
}

static void keyboard(unsigned char key, int x, int y)
{
    (void) x; (void) y;
    if (key == 'p')
        printf("light at %d %d degrees after %d passive moves\n", spin_x, spin_y, passive_moves);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(200, 200);
    glutCreateWindow("mouse light");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutPassiveMotionFunc(passive);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
