/* A grid of spheres, one material each: ambient grows along the rows, diffuse colour changes
 * along the columns, and the shininess of the specular highlight doubles from sphere to sphere.
 * 'l' moves the light to the other side, 'a' turns the global ambient light up. */
#include <GL/glut.h>

#define ROWS 3
#define COLS 4

static GLfloat light_x = 2.0f;
static GLfloat global_ambient = 0.2f;

static void init(void)
{
    GLfloat white[] = { 1.0f, 1.0f, 1.0f, 1.0f };
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

static void material(int row, int col)
{
    static const GLfloat diffuse[COLS][4] = {
        { 0.8f, 0.2f, 0.2f, 1.0f }, { 0.2f, 0.8f, 0.2f, 1.0f },
        { 0.2f, 0.3f, 0.9f, 1.0f }, { 0.8f, 0.7f, 0.2f, 1.0f } };
    GLfloat ambient[4], specular[4] = { 0.6f, 0.6f, 0.6f, 1.0f };
    GLfloat a = 0.1f + 0.25f * row;
    int i;
    for (i = 0; i < 3; i++)
        ambient[i] = a * diffuse[col][i];
    ambient[3] = 1.0f;
    glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse[col]);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, (GLfloat) (4 << (row + col)));
}

static void display(void)
{
    GLfloat position[] = { 0.0f, 3.0f, 3.0f, 0.0f };
    GLfloat ambient[] = { 0.0f, 0.0f, 0.0f, 1.0f };
    int row, col;

    position[0] = light_x;
    ambient[0] = ambient[1] = ambient[2] = global_ambient;
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    for (row = 0; row < ROWS; row++) {
        for (col = 0; col < COLS; col++) {
            glPushMatrix();
            glTranslatef(-3.0f + 2.0f * col, 2.0f - 2.0f * row, 0.0f);
            material(row, col);
            glutSolidSphere(0.8, 20, 14);
            glPopMatrix();
        }
    }
    glFlush();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-4.2, 4.2, -4.2 * h / w, 4.2 * h / w, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void) x; (void) y;
    if (key == 'l')
        light_x = -light_x;
    else if (key == 'a')
        global_ambient += 0.2f;
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(240, 180);
    glutCreateWindow("material grid");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
