// Scripted mode: steps that drive the viewer through the same actions as its menus, widgets
// and keys, for tests, benchmarks and documentation pictures. One step per line (or separated
// by ';'); '#' starts a comment:
//
//   open FILE | save FILE | set KEY VALUE | reset KEY | export heightmap|mesh|render FILE
//   layout four|single | view perspective|front|side|top | panel on|off | gridview on|off
//   orbit AZIMUTH ELEVATION [DISTANCE] | walk X Y BEARING | forward METRES | strafe METRES
//   turn YAW [PITCH] | walkpath X0 Y0 X1 Y1 STEPS | stopwalk
//   wait (until the scene is built and drawn) | frames N | measure N (frame times, in the report)
//   measure-orbit N (frame times while the camera orbits a degree per frame)
//   sleep SECONDS (frames go on: keys and mouse are handled) | waitfor FILE (until it exists)
//   screenshot FILE | quit
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "viewer/viewer.hpp"

namespace sansui::viewer {

class Script {
 public:
  /// Parses the steps; `source` names them in messages. Throws InputError "SOURCE:LINE: ...".
  static Script parse(std::string_view text, const std::string& source);

  /// Runs steps until one must wait for frames. Call once per frame, before Viewer::frame().
  /// Throws InputError when a wait times out.
  void advance(Viewer& viewer);
  bool finished() const {
    return next_ >= steps_.size() && frames_to_wait_ == 0 && sleep_until_s_ <= 0.0 && wait_for_file_.empty() && !waiting_idle_ &&
           path_steps_left_ == 0 && orbit_frames_left_ == 0;
  }

 private:
  struct Step {
    std::vector<std::string> words;
    std::string rest;  // the text after the first two words (a value with spaces)
    int line = 0;
  };
  void run(const Step& step, Viewer& viewer);

  std::string source_;
  std::vector<Step> steps_;
  std::size_t next_ = 0;
  int frames_to_wait_ = 0;
  bool waiting_idle_ = false;
  double idle_wait_started_ = 0.0;
  double sleep_until_s_ = 0.0;
  std::string wait_for_file_;
  // walkpath: steps still to walk and the step length
  int path_steps_left_ = 0;
  int orbit_frames_left_ = 0;
  double path_step_m_ = 0.0;
};

}  // namespace sansui::viewer
