// Passivity per contact episode (onset to separation), one home for the contact elements'
// measure (PolygonContact, StruckColumn3D): the net work an element does on the structures over an
// episode, −(W_separation − W_onset) of its work W = ∫ v·f_e dt (≤ 0: passive; a contact must
// never create energy), and that over the episode's gross work ∫ |v·f_e| dt, the scale of its
// round-off. The largest over the completed episodes is kept.
#pragma once

#include <limits>

namespace isopound {

class EpisodeWork {
 public:
  // An episode has ended: `net` J done on the structures over it, of `gross` J gross.
  void end(double net, double gross) {
    ++episodes_;
    if (net > max_net_) {
      max_net_ = net;
      max_relative_ = gross > 0 ? net / gross : 0.0;
    }
  }
  int episodes() const { return episodes_; }
  double max_net_work() const { return max_net_; }                // J; −inf before any episode
  double max_net_work_relative() const { return max_relative_; }  // of that episode's gross

 private:
  int episodes_ = 0;
  double max_net_ = -std::numeric_limits<double>::infinity();
  double max_relative_ = -std::numeric_limits<double>::infinity();
};

}  // namespace isopound
