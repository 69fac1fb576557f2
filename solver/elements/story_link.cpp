// A yielding storey: the uniaxial link plus its work along the drift path and its first yield.
#include "solver/elements/story_link.h"

#include <cmath>
#include <stdexcept>

namespace isopound {

StoryLink::StoryLink(std::string label, int lower, int upper, std::unique_ptr<UniaxialMaterial> law,
                     double yield_drift)
    : UniaxialLink(std::move(label), lower, upper, std::move(law)), yield_drift_(yield_drift) {
  if (!(yield_drift > 0)) throw std::invalid_argument("story link: yield drift must be > 0");
}

void StoryLink::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  UniaxialLink::set_trial(u, v);
  const double d = law().deformation();
  work_ = work_commit_ + 0.5 * (force_commit_ + law().force()) * (d - drift_commit_);
  yielded_ = yielded_commit_ || std::abs(d) >= yield_drift_;
}

void StoryLink::commit() {
  UniaxialLink::commit();
  work_commit_ = work_;
  force_commit_ = law().force();
  drift_commit_ = law().deformation();
  yielded_commit_ = yielded_;
}

void StoryLink::revert() {
  UniaxialLink::revert();
  work_ = work_commit_;
  yielded_ = yielded_commit_;
}

std::string StoryLink::output_name(int i) const {
  static const char* kNames[] = {"force", "drift", "z", "hysteretic_energy", "yielded"};
  return kNames[i];
}

Element::OutputKind StoryLink::output_kind(int i) const {
  return i == 4 ? OutputKind::kState : OutputKind::kContinuous;  // yielded
}

std::string StoryLink::output_unit(int i) const {
  static const char* kUnits[] = {"N", "m", "-", "J", "-"};
  return kUnits[i];
}

double StoryLink::output(int i) const {
  double values[5];
  outputs(values);
  return values[i];
}

}  // namespace isopound
