// script.h - the demo's replay scripts: timed drawing commands that make
// headless pictures reproducible. Format (see docs/demo.md):
//   # comment
//   frame <n> <command> <arguments...>
// Commands run at the start of simulation frame n (fixed dt each frame), in
// file order within a frame. This file only parses and checks syntax;
// app_script.cpp applies commands to the running demo.
#pragma once

#include <string>
#include <vector>

struct ScriptCommand {
  int frame = 0;
  int line = 0;               // 1-based line in the script file
  std::string verb;           // path, append, transition, ...
  std::vector<std::string> args;
};

// Reads and parses a script file; sorts commands by frame (stable). On a
// syntax error returns false with "file:line: message" in *error.
bool parse_script_file(const std::string& path, std::vector<ScriptCommand>* out, std::string* error);
bool parse_script_text(const std::string& text, const std::string& name, std::vector<ScriptCommand>* out,
                       std::string* error);

// Number parsing shared with the command-line parser: whole string must be
// a finite number.
bool parse_float(const std::string& s, float* out);
bool parse_int(const std::string& s, int* out);
