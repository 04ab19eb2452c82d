// script.cpp - parsing of replay scripts.
#include "script.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

bool parse_float(const std::string& s, float* out) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  float v = std::strtof(s.c_str(), &end);
  if (errno != 0 || end != s.c_str() + s.size() || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

bool parse_int(const std::string& s, int* out) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  long v = std::strtol(s.c_str(), &end, 10);
  if (errno != 0 || end != s.c_str() + s.size() || v < -1000000000L || v > 1000000000L) return false;
  *out = int(v);
  return true;
}

namespace {

bool all_floats(const std::vector<std::string>& a, size_t from) {
  float f;
  for (size_t i = from; i < a.size(); ++i)
    if (!parse_float(a[i], &f)) return false;
  return true;
}

bool is_on_off(const std::string& s) { return s == "on" || s == "off"; }

// Returns "" when the command's arguments are well formed, else a message.
std::string check(const ScriptCommand& c) {
  const auto& a = c.args;
  const std::string& v = c.verb;
  float f;
  int n;
  if (v == "path" || v == "append") {
    if (a.size() < 2 || a.size() % 2 || !all_floats(a, 0)) return v + " needs x z pairs of numbers";
  } else if (v == "stroke") {
    if (a.size() < 5 || a.size() % 2 == 0 || !parse_int(a[0], &n) || n < 0 || !all_floats(a, 1))
      return "stroke needs a frame count >= 0 and at least two x z pairs";
  } else if (v == "transition" || v == "splice") {
    if (a.size() != 2 || !parse_float(a[0], &f) || f < 0) return v + " needs <arc length >= 0> <name>";
  } else if (v == "move") {
    if (a.size() != 2 || !parse_int(a[0], &n) || !parse_float(a[1], &f)) return "move needs <marker#> <arc length>";
  } else if (v == "remove" || v == "select") {
    if (a.size() != 1 || !parse_int(a[0], &n)) return v + " needs <marker#>";
  } else if (v == "clear") {
    if (a.size() != 1 || (a[0] != "path" && a[0] != "markers" && a[0] != "all"))
      return "clear needs path, markers or all";
  } else if (v == "camera") {
    if ((a.size() != 3 && a.size() != 5) || !all_floats(a, 0))
      return "camera needs <yaw deg> <pitch deg> <distance> [<x> <z>]";
  } else if (v == "follow" || v == "ik" || v == "hud" || v == "footprints" || v == "skeleton") {
    if (a.size() != 1 || !is_on_off(a[0])) return v + " needs on or off";
  } else if (v == "trail") {
    if (a.empty() || a.size() > 2 || !is_on_off(a[0]) || (a.size() == 2 && (!parse_float(a[1], &f) || f <= 0)))
      return "trail needs on|off [interval seconds > 0]";
  } else if (v == "threshold") {
    if (a.size() != 1 || !parse_float(a[0], &f) || f <= 0) return "threshold needs a distance > 0 (metres)";
  } else if (v == "tool") {
    if (a.size() != 1 || (a[0] != "draw" && a[0] != "transition" && a[0] != "splice"))
      return "tool needs draw, transition or splice";
  } else if (v == "mouse") {
    // mouse down|up left|right|middle X Y   /   mouse move X Y
    bool button = a.size() == 4 && (a[0] == "down" || a[0] == "up") &&
                  (a[1] == "left" || a[1] == "right" || a[1] == "middle") && all_floats(a, 2);
    bool move = a.size() == 3 && a[0] == "move" && all_floats(a, 1);
    if (!button && !move) return "mouse needs 'down|up left|right|middle X Y' or 'move X Y' (pixels)";
  } else if (v == "wheel") {
    if (a.size() != 1 || !parse_float(a[0], &f)) return "wheel needs a number of steps";
  } else if (v == "key") {
    static const char* keys[] = {"delete", "1", "2", "3", "f", "h", "space", "f12"};
    bool known = false;
    for (const char* k : keys) known = known || (a.size() == 1 && a[0] == k);
    if (!known) return "key needs one of delete 1 2 3 f h space f12";
  } else if (v == "style" || v == "action" || v == "screenshot") {
    if (a.size() != 1) return v + " needs one argument";
  } else {
    return "unknown command '" + v + "'";
  }
  return "";
}

}  // namespace

bool parse_script_text(const std::string& text, const std::string& name, std::vector<ScriptCommand>* out,
                       std::string* error) {
  std::vector<ScriptCommand> cmds;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::vector<std::string> w;
    std::string word;
    while (words >> word) w.push_back(word);
    if (w.empty()) continue;
    auto fail = [&](const std::string& msg) {
      *error = name + ":" + std::to_string(line_no) + ": " + msg;
      return false;
    };
    int frame = 0;
    if (w[0] != "frame" || w.size() < 3) return fail("expected 'frame <n> <command> ...'");
    if (!parse_int(w[1], &frame) || frame < 0) return fail("frame number must be an integer >= 0");
    ScriptCommand c;
    c.frame = frame;
    c.line = line_no;
    c.verb = w[2];
    c.args.assign(w.begin() + 3, w.end());
    std::string problem = check(c);
    if (!problem.empty()) return fail(problem);
    if (c.verb == "stroke") {
      // A stroke is drawing by hand: the first point at `frame`, the others
      // appended evenly over the next `duration` frames.
      int duration = 0;
      parse_int(c.args[0], &duration);
      size_t points = (c.args.size() - 1) / 2;
      for (size_t k = 0; k < points; ++k) {
        ScriptCommand p;
        p.line = line_no;
        p.verb = k == 0 ? "path" : "append";
        p.frame = frame + (points > 1 ? int(std::lround(double(duration) * double(k) / double(points - 1))) : 0);
        p.args = {c.args[1 + 2 * k], c.args[2 + 2 * k]};
        cmds.push_back(p);
      }
      continue;
    }
    cmds.push_back(c);
  }
  std::stable_sort(cmds.begin(), cmds.end(),
                   [](const ScriptCommand& a, const ScriptCommand& b) { return a.frame < b.frame; });
  *out = std::move(cmds);
  return true;
}

bool parse_script_file(const std::string& path, std::vector<ScriptCommand>* out, std::string* error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *error = "cannot open script '" + path + "'";
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_script_text(ss.str(), path, out, error);
}
