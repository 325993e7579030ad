// Menus: kept as ids and entries so that a program's menu calls work, but never shown (there is
// no pointer to open them with in a headless run, and the GLFW window has no menu). The first
// menu call says so once on stderr.
#include <map>
#include <string>
#include <vector>

#include "glut_state.h"

using namespace ffc::glut;

namespace {

struct Menu {
  std::vector<std::string> entries;
  void* data = nullptr;
  Callback<int> callback;
  Callback<> destroy;
};

struct Menus {
  std::map<int, Menu> menus;
  int next = 1;
  int current = 0;
};

Menus& menus() {
  static Menus m;
  return m;
}

void say() {
  say_once("menus", "menu calls are accepted and kept, but no menu is ever shown");
}

Menu* current_menu(const char* caller) {
  say();
  auto it = menus().menus.find(menus().current);
  if (it == menus().menus.end()) error(" ERROR:  Function <%s> called with no current menu defined.", caller);
  return &it->second;
}

int create(const Callback<int>& cb) {
  require_init("glutCreateMenu");
  say();
  Menus& m = menus();
  const int id = m.next++;
  m.menus[id].callback = cb;
  m.current = id;
  return id;
}

}  // namespace

extern "C" {

int glutCreateMenu(void (*callback)(int menu)) {
  Callback<int> cb;
  cb.set(callback);
  return create(cb);
}
int glutCreateMenuUcall(void (*callback)(int menu, void* user_data), void* user_data) {
  Callback<int> cb;
  cb.set(callback, user_data);
  return create(cb);
}
void glutDestroyMenu(int menu) {
  say();
  auto it = menus().menus.find(menu);
  if (it == menus().menus.end()) return;
  if (it->second.destroy) it->second.destroy();
  menus().menus.erase(it);
  if (menus().current == menu) menus().current = 0;
}
int glutGetMenu(void) {
  say();
  return menus().current;
}
void glutSetMenu(int menu) {
  say();
  if (menus().menus.count(menu)) menus().current = menu;
}
void glutAddMenuEntry(const char* label, int value) {
  (void)value;
  current_menu("glutAddMenuEntry")->entries.push_back(label ? label : "");
}
void glutAddSubMenu(const char* label, int subMenu) {
  (void)subMenu;
  current_menu("glutAddSubMenu")->entries.push_back(label ? label : "");
}
void glutChangeToMenuEntry(int item, const char* label, int value) {
  (void)value;
  Menu* m = current_menu("glutChangeToMenuEntry");
  if (item >= 1 && item <= int(m->entries.size())) m->entries[size_t(item - 1)] = label ? label : "";
}
void glutChangeToSubMenu(int item, const char* label, int value) {
  glutChangeToMenuEntry(item, label, value);
}
void glutRemoveMenuItem(int item) {
  Menu* m = current_menu("glutRemoveMenuItem");
  if (item >= 1 && item <= int(m->entries.size())) m->entries.erase(m->entries.begin() + (item - 1));
}
void glutAttachMenu(int button) {
  (void)button;
  current_window("glutAttachMenu");
  current_menu("glutAttachMenu");
}
void glutDetachMenu(int button) {
  (void)button;
  current_window("glutDetachMenu");
  current_menu("glutDetachMenu");
}
void glutSetMenuData(void* data) { current_menu("glutSetMenuData")->data = data; }
void* glutGetMenuData(void) { return current_menu("glutGetMenuData")->data; }
void glutSetMenuFont(int menuID, void* font) {
  (void)menuID, (void)font;
  say();
}
void glutMenuDestroyFunc(void (*callback)(void)) { current_menu("glutMenuDestroyFunc")->destroy.set(callback); }
void glutMenuDestroyFuncUcall(void (*callback)(void* user_data), void* user_data) {
  current_menu("glutMenuDestroyFuncUcall")->destroy.set(callback, user_data);
}
// No menu is ever in use, so the status callbacks are never called.
void glutMenuStateFunc(void (*callback)(int state)) {
  (void)callback;
  say();
}
void glutMenuStatusFunc(void (*callback)(int status, int x, int y)) {
  (void)callback;
  say();
}
void glutMenuStatusFuncUcall(void (*callback)(int status, int x, int y, void* user_data), void* user_data) {
  (void)callback, (void)user_data;
  say();
}

}  // extern "C"
