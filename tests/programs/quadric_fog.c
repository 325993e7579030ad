/* GLU quadrics in fog: a row of spheres, cylinders, disks and partial disks going into the
 * distance, drawn smooth, flat and as lines. 'f' steps the fog mode (linear, exp, exp2, off),
 * 'd' makes the fog denser. */
#include <GL/glut.h>
#include <stdio.h>

static GLUquadricObj *quadric;
static int fog_mode;
static GLfloat density = 0.15f;

static void init(void)
{
    GLfloat fog_colour[] = { 0.5f, 0.5f, 0.55f, 1.0f };
    GLfloat position[] = { 0.5f, 1.0f, 1.0f, 0.0f };
    GLfloat mat[] = { 0.3f, 0.6f, 0.8f, 1.0f };

    glClearColor(0.5f, 0.5f, 0.55f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, mat);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glFogfv(GL_FOG_COLOR, fog_colour);
    glFogf(GL_FOG_START, 3.0f);
    glFogf(GL_FOG_END, 12.0f);
    glHint(GL_FOG_HINT, GL_DONT_CARE);
    glEnable(GL_FOG);
    quadric = gluNewQuadric();
}

static void row_of_quadrics(GLfloat x)
{
    int i;
    for (i = 0; i < 4; i++) {
        glPushMatrix();
        glTranslatef(x, 0.0f, -2.5f * i);
        switch ((int) (x + 3.0f) / 2) {
        case 0:
            gluQuadricNormals(quadric, GLU_SMOOTH);
            gluQuadricDrawStyle(quadric, GLU_FILL);
            gluSphere(quadric, 0.6, 20, 14);
            break;
        case 1:
            gluQuadricNormals(quadric, GLU_FLAT);
            gluQuadricDrawStyle(quadric, GLU_FILL);
            glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
            gluCylinder(quadric, 0.5, 0.2, 1.0, 16, 3);
            break;
        case 2:
            gluQuadricNormals(quadric, GLU_SMOOTH);
            gluQuadricDrawStyle(quadric, GLU_FILL);
            gluDisk(quadric, 0.2, 0.6, 20, 2);
            break;
        default:
            gluQuadricNormals(quadric, GLU_SMOOTH);
            gluQuadricDrawStyle(quadric, GLU_LINE);
            gluPartialDisk(quadric, 0.1, 0.6, 16, 3, 30.0, 240.0);
            break;
        }
        glPopMatrix();
    }
}

static void display(void)
{
    static const GLenum modes[] = { GL_LINEAR, GL_EXP, GL_EXP2 };
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (fog_mode < 3) {
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, modes[fog_mode]);
        glFogf(GL_FOG_DENSITY, density);
    } else {
        glDisable(GL_FOG);
    }
    row_of_quadrics(-3.0f);
    row_of_quadrics(-1.0f);
    row_of_quadrics(1.0f);
    row_of_quadrics(3.0f);
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (GLdouble) w / h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 5.0, 0.0, 0.0, -3.0, 0.0, 1.0, 0.0);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void) x; (void) y;
    if (key == 'f')
        fog_mode = (fog_mode + 1) % 4;
    else if (key == 'd')
        density *= 1.5f;
    printf("fog mode %d density %.3f\n", fog_mode, density);
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(200, 200);
    glutCreateWindow("quadrics in fog");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
