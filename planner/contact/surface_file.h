#pragma once
// The per-model surface sidecar file (YAML). Format `stanceplan/surfaces@1`:
//
//   format: stanceplan/surfaces@1
//   surfaces:
//     - name: l_sole                       # unique in the file
//       link: l_ankle_roll                 # a link of the model
//       normal: [0, 0, -1]                 # outward normal, link frame
//       vertices: [[0.12, 0.06, -0.1], [0.12, -0.06, -0.1], ...]   # link frame, m,
//                                          # counter-clockwise seen from outside (about normal)
//       x_axis: [1, 0, 0]                  # optional: surface x axis (projected on the plane)
//     - name: seat
//       link: chair
//       box_face: +z                       # derive from the link's box collision geometry:
//                                          # one of +x -x +y -y +z -z
//       box_index: 0                       # optional: which box of the link (default 0)
//       inset: 0.01                        # optional: shrink the face by this margin (m)
//       x_axis: [0, 1, 0]                  # optional, as with vertices
//     - name: r_sole
//       link: r_foot
//       face: -z                           # the flat face of the link's collision geometry
//                                          # nearest this direction (link frame): +x ... -z or
//                                          # [x, y, z] (link_faces.h)
//       inset: 0.005                       # optional, as with box_face
//       x_axis: [1, 0, 0]                  # optional, as with vertices
//     - name: index_tip
//       link: index_distal
//       point: [0, 0, 0.03]                # a sphere's centre, link frame (a round fingertip):
//       radius: 0.008                      # its radius (m, >= 0); only s1 of a contact
//
// Each surface gives exactly one of vertices, box_face, face and point, and only the keys of its
// kind: any other key is refused with its line ("surfaces[2].x_axsi: unknown field (expected one
// of: name, link, normal, vertices, x_axis)").
//
// Errors name the file, the line, the surface and the fault, e.g.
//   "humanoid.surfaces.yaml:12: surface "l_palm": link "l_hand" is not in model "humanoid"".
#include <string>
#include <vector>

#include "planner/contact/surface.h"
#include "planner/model/model.h"

namespace stanceplan {

// Throws InputError on any fault.
std::vector<Surface> load_surface_file(const std::string& path, const Model& model);

// One face ("+x" ... "-z", in the box's own frame) of box `box_index` among the link's
// collision boxes, shrunk by `inset`, as a surface named `name` with its normal pointing out of the
// box. Its x axis: `x_axis_L` (link frame) projected on the face when given, else the box's first
// axis in the face (link_faces.h, box_face). Throws InputError when the link has no such box or
// the face name is unknown.
Surface surface_from_box_face(const Model& model, int link, int box_index, const std::string& face,
                              double inset, const std::string& name,
                              const Eigen::Vector3d* x_axis_L = nullptr);

}  // namespace stanceplan
