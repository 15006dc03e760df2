// cut_probe.h: the orthogonal cut by the first tool mesh (a [[mesh]] with rake_angle, or a file
// with tool_tip, its rake angle measured by tool_measure.h) through the workpiece.
//
// Per row: the tool's travel along x (m), the cutting force Fc (against the cutting direction
// +x of the tool frame) and the thrust force Ft (+z, away from the workpiece), both per unit
// width of the workpiece (N/m), and the chip's thickness then (m; 0 while fewer than 10 chip
// particles have left the edge region); for a compliant tool (a rigid body on a spring to its
// holder) also its deflection from the holder along x and z (m), and at the end its
// vibration analysis (tool_vibration.h): summary.json "tool" and tool_spectrum.csv. At the end: the cut's setup in
// results.h5, and the force statistics and chip metrics (finish_cut, from the series' columns read by name) in
// summary.json "cutting" and "chip", the chip surface, the picture and the result table. It keeps no state between
// rows: the tool's place is the mesh's offset, in the engine state.
#pragma once

#include "app/observers/observer.h"
#include "postprocess/cut_report.h"

namespace swarf {

struct Model;

class CutProbe final : public Observer {
 public:
  /// The cut of 'model' (held by reference), or null when it has no tool mesh or no workpiece.
  static std::unique_ptr<CutProbe> of(const Model& model);
  /// 'tool_body': the index of the tool's rigid body in model.bodies when it is a compliant tool
  /// (on a spring along x and z), else -1.
  CutProbe(const Model& model, const CutSetup& setup, int tool_mesh, int tool_body = -1)
      : model_(model), setup_(setup), tool_mesh_(tool_mesh), tool_body_(tool_body) {}
  std::string_view name() const override { return "cut"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void write_results(H5File& f) const override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;
  /// The cut's setup at the start of the run (the tip where the tool starts).
  const CutSetup& setup() const { return setup_; }

 private:
  /// The tool's sharp tip now (m): it moves with the tool's mesh.
  Vec3 tool_tip() const;
  /// The setup with the tip where the tool is now (as results.h5 and the analysis record it).
  CutSetup setup_now() const;

  const Model& model_;
  CutSetup setup_;  ///< at the start of the run (tool_tip: the tip at t = 0)
  int tool_mesh_;
  int tool_body_;
};

}  // namespace swarf
