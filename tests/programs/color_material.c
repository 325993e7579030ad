/* Colour material: glColor drives the material through glColorMaterial. A left click picks the
 * next colour, a right click the next material property the colour drives, a middle click
 * switches the side lit from the front to both faces. */
#include <GL/glut.h>
#include <stdio.h>

static const GLfloat colours[][3] = {
    { 0.9f, 0.2f, 0.2f }, { 0.2f, 0.8f, 0.3f }, { 0.2f, 0.4f, 0.9f }, { 0.9f, 0.8f, 0.1f } };
static const GLenum modes[] = { GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_AMBIENT, GL_SPECULAR, GL_EMISSION };
static const char *mode_names[] = { "ambient and diffuse", "diffuse", "ambient", "specular", "emission" };
static int colour, mode;
static GLenum face = GL_FRONT;

static void init(void)
{
    GLfloat specular[] = { 1.0f, 1.0f, 1.0f, 1.0f };
    GLfloat position[] = { 1.0f, 1.0f, 1.0f, 0.0f };

    glClearColor(0.2f, 0.2f, 0.2f, 0.0f);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 25.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColorMaterial(face, modes[mode]);
    glColor3fv(colours[colour]);
    glPushMatrix();
    glTranslatef(-0.6f, 0.0f, 0.0f);
    glutSolidSphere(0.55, 24, 16);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.7f, 0.0f, 0.0f);
    glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
    glColor3f(colours[colour][2], colours[colour][0], colours[colour][1]);
    glutSolidCube(0.7);
    glPopMatrix();
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.5, 1.5, -1.5 * h / w, 1.5 * h / w, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void mouse(int button, int state, int x, int y)
{
    if (state != GLUT_DOWN)
        return;
    if (button == GLUT_LEFT_BUTTON)
        colour = (colour + 1) % 4;
    else if (button == GLUT_RIGHT_BUTTON)
        mode = (mode + 1) % 5;
    else if (button == GLUT_MIDDLE_BUTTON)
        face = face == GL_FRONT ? GL_FRONT_AND_BACK : GL_FRONT;
    printf("click at %d,%d: colour %d drives %s\n", x, y, colour, mode_names[mode]);
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(200, 200);
    glutCreateWindow("colour material");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutMainLoop();
    return 0;
}
