// Mesh files (OBJ, OFF, PLY, STL) read through OpenMesh's readers, after a check of the file's
// structure: OpenMesh's readers trust what a file declares (a corrupt count makes the OFF and PLY
// readers allocate gigabytes or loop for minutes, a malformed vertex line crashes the OBJ reader),
// so OBJ, OFF and PLY files are walked first and refused with a clear message. OpenMesh's own complaints (invalid vertex indices, faces it could not add) are captured
// rather than printed, and make the file an error too: a mesh never silently loses faces.
#pragma once
#include <string>

#include "scene/description.h"

namespace ffc::scene {

// Reads the file; polygons are triangulated by OpenMesh, vertex normals kept when the file has
// them (OBJ vn, OFF NOFF, PLY nx/ny/nz). Throws std::runtime_error with a message that names the
// file and what is wrong with it: missing, unreadable, unsupported extension, corrupt, no triangles,
// coordinates that are not finite.
MeshFile read_mesh_file(const std::string& path);

}  // namespace ffc::scene
