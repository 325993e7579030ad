/* Selection and feedback: a square, a triangle and a sphere, each with a name. A left click
 * picks with gluPickMatrix in GL_SELECT mode, prints the hit records and draws the picked
 * objects brighter; 'f' runs the scene through GL_FEEDBACK (GL_3D_COLOR, with glPassThrough
 * markers between the objects) and prints what comes back. */
#include <GL/glut.h>
#include <stdio.h>

#define SQUARE 1
#define TRIANGLE 2
#define SPHERE 3

static int picked[4];
static GLUquadricObj *quadric;

static void objects(GLenum mode)
{
    glColor3f(picked[SQUARE] ? 1.0f : 0.5f, 0.1f, 0.1f);
    if (mode == GL_SELECT) glLoadName(SQUARE);
    if (mode == GL_FEEDBACK) glPassThrough((GLfloat) SQUARE);
    glRectf(-0.9f, -0.9f, -0.1f, -0.1f);

    if (mode == GL_SELECT) glPushName(TRIANGLE);
    if (mode == GL_FEEDBACK) glPassThrough((GLfloat) TRIANGLE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.1f, picked[TRIANGLE] ? 1.0f : 0.5f, 0.1f);
    glVertex3f(0.1f, -0.9f, -0.25f);
    glVertex3f(0.9f, -0.9f, 0.25f);
    glVertex3f(0.5f, -0.1f, 0.0f);
    glEnd();
    if (mode == GL_SELECT) glPopName();

    if (mode == GL_SELECT) glLoadName(SPHERE);
    if (mode == GL_FEEDBACK) glPassThrough((GLfloat) SPHERE);
    glColor3f(0.1f, 0.1f, picked[SPHERE] ? 1.0f : 0.5f);
    glPushMatrix();
    glTranslatef(0.0f, 0.45f, 0.0f);
    gluSphere(quadric, 0.4, 12, 8);
    glPopMatrix();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    objects(GL_RENDER);
    glutSwapBuffers();
}

static void projection(void)
{
    glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    projection();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void pick(int x, int y)
{
    GLuint buffer[64], *p;
    GLint viewport[4], hits, i, j;

    glGetIntegerv(GL_VIEWPORT, viewport);
    glSelectBuffer(64, buffer);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(0);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluPickMatrix((GLdouble) x, (GLdouble) (viewport[3] - y), 5.0, 5.0, viewport);
    projection();
    glMatrixMode(GL_MODELVIEW);
    objects(GL_SELECT);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    hits = glRenderMode(GL_RENDER);

    picked[SQUARE] = picked[TRIANGLE] = picked[SPHERE] = 0;
    printf("click at %d,%d: %d hit%s\n", x, y, hits, hits == 1 ? "" : "s");
    for (i = 0, p = buffer; i < hits; i++) {
        GLuint names = *p++;
        double zmin = *p++ / 4294967295.0, zmax = *p++ / 4294967295.0;
        printf("  %u name%s, depth %.3f to %.3f:", names, names == 1 ? "" : "s", zmin, zmax);
        for (j = 0; j < (GLint) names; j++, p++) {
            printf(" %u", *p);
            if (*p <= SPHERE) picked[*p] = 1;
        }
        printf("\n");
    }
}

static void feedback(void)
{
    GLfloat buffer[4096];
    GLint n, i = 0, polygons = 0;

    glFeedbackBuffer(4096, GL_3D_COLOR, buffer);
    glRenderMode(GL_FEEDBACK);
    objects(GL_FEEDBACK);
    n = glRenderMode(GL_RENDER);
    printf("feedback: %d values\n", n);
    while (i < n) {
        GLint token = (GLint) buffer[i++];
        if (token == GL_PASS_THROUGH_TOKEN) {
            printf("  pass through %.0f\n", buffer[i++]);
        } else if (token == GL_POLYGON_TOKEN) {
            GLint count = (GLint) buffer[i++], k;
            polygons++;
            /* the square and the triangle in full; the sphere's many polygons are counted */
            if (polygons <= 3)
                printf("  polygon of %d\n", count);
            for (k = 0; k < count; k++, i += 7)
                if (polygons <= 3)
                    printf("    %.2f %.2f %.3f  %.2f %.2f %.2f %.2f\n", buffer[i], buffer[i + 1], buffer[i + 2],
                           buffer[i + 3], buffer[i + 4], buffer[i + 5], buffer[i + 6]);
        } else {
            printf("  token %d\n", token);
            break;
        }
    }
    printf("  %d polygons in all\n", polygons);
}

static void mouse(int button, int state, int x, int y)
{
    if (button == GLUT_LEFT_BUTTON && state == GLUT_DOWN) {
        pick(x, y);
        glutPostRedisplay();
    }
}

static void keyboard(unsigned char key, int x, int y)
{
    (void) x; (void) y;
    if (key == 'f')
        feedback();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(200, 200);
    glutCreateWindow("selection and feedback");
    glEnable(GL_DEPTH_TEST);
    quadric = gluNewQuadric();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
