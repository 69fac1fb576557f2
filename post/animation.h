// Animation frames of a run as plain meshes (points, cells, named Float64 arrays), one per output
// time: 2D runs as a stick model in the x-z plane (slabs, columns, bearings, walls, contacts).
// Displacements are drawn magnified by `scale` (gaps too, so bodies touch exactly when in contact).
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "post/figure.h"
#include "post/run_data.h"

namespace isopound::post {

// A cell: VTK cell type number (3 line, 9 quad, 7 polygon) and its point indices.
struct MeshCell {
  int vtk_type = 3;
  std::vector<int> points;
};

struct MeshArray {
  std::string name;
  int components = 1;
  std::vector<double> values;  // components per point or per cell
};

// What a cell is (cell array "block"): the blocks of a frame. The mesh and the .vtu writer know
// no dimension: a 3D frame builder adds hexahedra (VTK type 12) for extruded slabs, polygons (7)
// for contact overlaps and vertices with vector arrays for forces, new Block values after these,
// and the writer, the .pvd and the tests' reader stay as they are.
// 3D frames add the contact force vectors as lines from the overlap's centroid.
enum class Block {
  kSlab = 0,
  kColumn = 1,
  kBearing = 2,
  kWall = 3,
  kContact = 4,
  kNormalForce = 5,
  kTangentialForce = 6,
  kRubber = 7  // a bumper's rubber strips (3D)
};

struct FrameMesh {
  double time = 0.0;                          // s
  std::vector<std::array<double, 3>> points;  // m, drawing coordinates (x right, y, z up)
  std::vector<MeshCell> cells;
  std::vector<MeshArray> point_data;  // one value set per point
  std::vector<MeshArray> cell_data;   // one value set per cell
  std::vector<MeshArray> field_data;  // whole-frame values (the writer adds TimeValue)
};

struct AnimationOptions {
  double scale = 1.0;           // displacement magnification
  double slab_width = 12.0;     // m, drawn width of a floor slab
  double slab_thickness = 0.4;  // m
  double force_length = 3.0;    // m, 3D: drawn length of the largest contact force of the run
};

// The frame at time t (histories interpolated linearly between rows); a 3D run's frame is
// animation_frame3d's (animation3d.h). 2D arrays:
//   point data: displacement (3, m, true not scaled), absolute_acceleration (3, m/s^2),
//               contact_depth_offset (3, m: see below), gap_offset (3, m: see below)
//   cell data:  block, drift_ratio (columns), bearing_force (bearings, N), contact_force (3, N,
//               on the body, contacts), penetration (contacts, m), normal_force (N, |F|)
// Contact cells exist only in frames where that contact's force or penetration is > 0.
// contact_depth_offset of a contact cell's point is its offset from the overlap's middle along
// the contact normal (zero elsewhere): a viewer that moves every point by (X − 1) × this draws
// the overlap X times deeper and nothing else changes (view.py's exaggeration).
// gap_offset of a point of a wall or a neighbour is the gap that separates it from the building
// at rest (zero elsewhere): a viewer that moves every point by (X − S) × (displacement +
// gap_offset) draws the frame at displacement scale X with the gaps × X, so that bodies still
// touch exactly when in contact (view.py's displacement scale). 3D frames draw gaps true (walls
// are not moved by S): there the viewer moves by (X − 1) × gap_offset.
FrameMesh animation_frame(const RunData& run, double t, const AnimationOptions& options);

// A picture of one frame (x-z view, equal axes, coloured by block, with the time and the scale):
// the README's preview of an animation, and a quick look without ParaView.
Figure frame_figure(const FrameMesh& mesh, double scale, int width = 900, int height = 520);

// The caption of a frame picture: the title (time and displacement scale) at the top, and the
// legend in a row below it, `spacing` px apart, `drop` px below the top: a short line in each
// block's colour and the block's name.
void add_frame_caption(Figure& fig, double time, double scale, std::span<const char* const> names,
                       std::span<const Rgb> colours, double spacing, double drop);

// The .pvd collection (ParaView Data) for files written at times.
std::string pvd_text(const std::vector<double>& times, const std::vector<std::string>& files);

}  // namespace isopound::post
