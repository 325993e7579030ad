// The headline: how many triangles GL_FLAT needs, against GL_SMOOTH with averaged normals, to reach
// the same shading error; read off the error-against-triangles curves by interpolation.
#pragma once
#include <string>
#include <vector>

#include "report/sweep.h"

namespace ffc::report {

struct CurvePoint {
  double triangles = 0, rmse = 0;
  double ms = 0;  // run time per frame, if known (0: not)
};

// The triangles a curve needs to bring its RMSE down to `target`, interpolating log(triangles)
// linearly in log(rmse) between the two points around the curve's first crossing of the target.
// A curve already at or below the target at its first point gives that point's triangles
// (`at_start`: an upper bound); one that never gets there is extrapolated as a power law through its
// last two points (`extrapolated`) when they still fall, and not reached otherwise (triangles NaN).
struct Reach {
  double triangles = 0;
  double ms = 0;              // the run time per frame there, interpolated alike (0: unknown)
  bool reached = false;       // within the curve (interpolated) or at its start
  bool at_start = false;
  bool extrapolated = false;  // beyond the curve's last point
};
Reach triangles_to_reach(std::vector<CurvePoint> curve, double target);

// One target RMSE and what each shading needs for it.
struct Crossing {
  double target_rmse = 0;
  Reach flat, smooth;
  double ratio = 0;  // flat triangles / smooth triangles
};

struct Headline {
  std::string scene, backend;
  std::vector<Crossing> crossings;  // the ladder of targets
  Crossing main;                   // the lowest target both reach without extrapolating
  bool found = false;
};

// For each lighting setup in the rows: flat against smooth-average on `backend`, over the targets
// 16, 8, 4, 2, 1, 0.5 steps (those both curves give a number for; extrapolations flagged). `main`
// is the lowest target both reach within the sweep.
std::vector<Headline> headlines(const std::vector<Row>& rows, const std::string& backend = "mesa");

// "0.86", "4.1", "17": a ratio for people.
std::string ratio_text(double ratio);

// The curve of one (scene, shading, backend): (triangles, rmse, ms) by depth.
std::vector<CurvePoint> curve(const std::vector<Row>& rows, const std::string& scene, const std::string& shading,
                              const std::string& backend);

}  // namespace ffc::report
