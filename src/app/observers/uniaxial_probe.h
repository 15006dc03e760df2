// uniaxial_probe.h: the uniaxial bar ([uniaxial]) measured against the rod law.
//
// Per row: the nominal strain between the grips, the stress from the grips' reactions, the
// rod-law prediction for the strain history so far (BarPrediction, which must follow every
// step: it carries a plastic shift) and the stress through the bar's mid-plane. At the end
// the loop is fitted (analyze_loop) from the series' strain and stress columns, read by
// name, into summary.json "uniaxial" and the printed table. The checkpoint state is the
// prediction's; the loop's samples are the series rows, which the checkpoint carries anyway.
#pragma once

#include "app/observers/observer.h"
#include "postprocess/hysteresis.h"
#include "swarf/step_listener.h"

namespace swarf {

struct Model;

class UniaxialProbe final : public Observer, public StepListener {
 public:
  /// For a model with [uniaxial] (model.uniaxial.enabled), held by reference.
  explicit UniaxialProbe(const Model& model);
  std::string_view name() const override { return "uniaxial"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void visit_state(StateArchive& ar) override;
  StepListener* step_listener() override { return this; }
  void finish(const RunEnd& end, nlohmann::json& summary) override;

  /// The prediction follows the grips' strain at the end of each step.
  void after_step(Simulation& sim) override;

 private:
  double bar_strain(double t) const;               ///< nominal strain between the grips at time t (s), 1
  double bar_stress(const Simulation& sim) const;  ///< from the grips' reactions, Pa
  double midplane_stress() const;                  ///< through the rods crossing the mid-plane, Pa
  /// The path segment (0, 1, ...) at time t (s).
  int segment_at(double t) const;

  const Model& model_;
  BarPrediction prediction_;
  double predicted_ = 0;  ///< the prediction at the last step, Pa (0 before the first)
};

}  // namespace swarf
