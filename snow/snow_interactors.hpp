// Things that press into the snow, and the stamps each leaves over one frame.
// A walker puts a foot down every half stride, left and right of its path: every
// footfall whose distance lies in the frame's interval is stamped, however many that
// is, so a walker faster than one step per frame leaves every print. In snow deeper
// than its feet lift, the feet drag through it and the prints join into a furrow
// (seed 5.2.2: "the feet never rise above the snow surface"). A vehicle's two wheel
// ruts are capsules between marks every `rutStep` along its path: a frame stamps from
// the last mark passed before it to the last mark passed in it, so a parked vehicle
// stamps nothing and a creeping one stamps every few frames, never leaving a gap.
#pragma once
#include <vector>

#include "snow/scripted_path.hpp"
#include "snow/snow_stamp.hpp"

namespace wg::snow {

struct Walker {
  ScriptedPath path;
  float stepLength = 0.75f;  // one footfall to the next (half a stride)
  float footSpacing = 0.18f;  // between the centres of the left and right feet
  FootShape foot;
  float sink = 0.3f;  // how far a foot would sink in bottomless snow
  float footLift = 0.15f;  // feet clear snow shallower than this between steps
};

struct Vehicle {
  ScriptedPath path;
  float track = 1.5f;       // between the wheel centres, left to right
  float wheelWidth = 0.22f;
  float sink = 0.5f;        // a loaded wheel packs everything under it
  float rutStep = 0.02f;    // half a 4 cm texel: finer moves wait for the next frame
};

// Stamps for the interval (t0, t1] in seconds.
void walkerStamps(const Walker& walker, double t0, double t1, const SnowCover& cover, std::vector<Stamp>& out);
void vehicleStamps(const Vehicle& vehicle, double t0, double t1, const SnowCover& cover, std::vector<Stamp>& out);

// Where the walker's k-th footfall lands (k from 0; even left, odd right).
glm::vec2 footfall(const Walker& walker, int k);
// The footfalls k of the interval (t0, t1]: first..last, inclusive (empty when first > last).
struct FootfallRange {
  int first = 0, last = -1;
};
FootfallRange footfallsBetween(const Walker& walker, double t0, double t1);

}  // namespace wg::snow
