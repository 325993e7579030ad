/* A scene of GLUT shapes compiled once into display lists: a teapot in the middle, the
 * platonic solids, a cone and a torus around it, each with its own material list. A timer turns
 * the scene 15 degrees every 100 ms; 'w' swaps the solid shapes for wire ones. */
#include <GL/glut.h>

static GLuint solid_list, wire_list, materials;
static int angle, wire;

static void make_materials(void)
{
    static const GLfloat colours[4][4] = {
        { 0.8f, 0.5f, 0.2f, 1.0f }, { 0.3f, 0.6f, 0.9f, 1.0f },
        { 0.5f, 0.8f, 0.4f, 1.0f }, { 0.8f, 0.3f, 0.6f, 1.0f } };
    GLfloat white[] = { 0.7f, 0.7f, 0.7f, 1.0f };
    int i;
    materials = glGenLists(4);
    for (i = 0; i < 4; i++) {
        glNewList(materials + i, GL_COMPILE);
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colours[i]);
        glMaterialfv(GL_FRONT, GL_SPECULAR, white);
        glMaterialf(GL_FRONT, GL_SHININESS, 20.0f + 20.0f * i);
        glEndList();
    }
}

static void place(GLfloat x, GLfloat y, int material)
{
    glCallList(materials + material);
    glTranslatef(x, y, 0.0f);
}

static void scene(int solid)
{
    glPushMatrix();
    glCallList(materials);
    if (solid) glutSolidTeapot(0.5); else glutWireTeapot(0.5);
    glPopMatrix();

    glPushMatrix(); place(-1.2f, 1.0f, 1);
    glScalef(0.4f, 0.4f, 0.4f);
    if (solid) glutSolidDodecahedron(); else glutWireDodecahedron();
    glPopMatrix();

    glPushMatrix(); place(0.0f, 1.1f, 2);
    glScalef(0.45f, 0.45f, 0.45f);
    if (solid) glutSolidIcosahedron(); else glutWireIcosahedron();
    glPopMatrix();

    glPushMatrix(); place(1.2f, 1.0f, 3);
    glScalef(0.45f, 0.45f, 0.45f);
    if (solid) glutSolidOctahedron(); else glutWireOctahedron();
    glPopMatrix();

    glPushMatrix(); place(-1.2f, -1.0f, 2);
    glScalef(0.45f, 0.45f, 0.45f);
    if (solid) glutSolidTetrahedron(); else glutWireTetrahedron();
    glPopMatrix();

    glPushMatrix(); place(0.0f, -1.1f, 3);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    if (solid) glutSolidCone(0.35, 0.6, 16, 4); else glutWireCone(0.35, 0.6, 16, 4);
    glPopMatrix();

    glPushMatrix(); place(1.2f, -1.0f, 1);
    if (solid) glutSolidTorus(0.1, 0.3, 10, 20); else glutWireTorus(0.1, 0.3, 10, 20);
    glPopMatrix();

    glPushMatrix(); place(-1.5f, 0.0f, 0);
    glRotatef(20.0f, 1.0f, 1.0f, 0.0f);
    if (solid) glutSolidCube(0.4); else glutWireCube(0.4);
    glPopMatrix();
}

static void init(void)
{
    GLfloat position[] = { 2.0f, 3.0f, 4.0f, 0.0f };
    glClearColor(0.05f, 0.05f, 0.1f, 0.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);
    make_materials();
    solid_list = glGenLists(2);
    wire_list = solid_list + 1;
    glNewList(solid_list, GL_COMPILE);
    scene(1);
    glEndList();
    glNewList(wire_list, GL_COMPILE);
    scene(0);
    glEndList();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef((GLfloat) angle, 0.0f, 1.0f, 0.0f);
    glCallList(wire ? wire_list : solid_list);
    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble) w / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.5, 5.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

static void turn(int value)
{
    (void) value;
    angle = (angle + 15) % 360;
    glutPostRedisplay();
    glutTimerFunc(100, turn, 0);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void) x; (void) y;
    if (key == 'w') {
        wire = !wire;
        glutPostRedisplay();
    }
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(200, 200);
    glutCreateWindow("shapes in display lists");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(100, turn, 0);
    glutMainLoop();
    return 0;
}
