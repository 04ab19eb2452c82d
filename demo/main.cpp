// main.cpp - smg-demo: draw a path with the mouse and watch a motion-capture
// character follow it, with transition (gait) and splice (upper-body
// action) points, on the libsmg runtime. Also renders scripted drawings to
// PNG headlessly (--script/--frames/--screenshot) for docs and CI.
#include "app.h"
#include "gl_api.h"
#include "offscreen.h"

#include <SDL.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>
// Dear ImGui 1.88 renamed the SDL2 backend header; Debian 12 ships 1.86.
#if __has_include(<imgui_impl_sdl2.h>)
#include <imgui_impl_sdl2.h>
#else
#include <imgui_impl_sdl.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <unistd.h>

// The default graph's file name (mk/demo.mk passes the one it bakes); no
// directory is compiled in, so the binary works wherever the tree or the
// binary is moved.
#ifndef SMG_DEMO_DEFAULT_GRAPH
#define SMG_DEMO_DEFAULT_GRAPH "default.smg"
#endif

using namespace demo_gl;

int App::viewport_width() const {
  if (headless || !window) return options.width;
  int w = 0, h = 0;
  SDL_GetWindowSize(window, &w, &h);
  return w;
}

int App::viewport_height() const {
  if (headless || !window) return options.height;
  int w = 0, h = 0;
  SDL_GetWindowSize(window, &w, &h);
  return h;
}

namespace {

bool file_exists(const std::string& path) {
  return access(path.c_str(), R_OK) == 0;
}

// The default graph: beside the executable (build/ holds both), else in
// build/ under the working directory (the repository root). When neither
// exists, the path beside the executable, for the error message.
const std::string& default_graph() {
  static std::string path;
  if (!path.empty()) return path;
  char exe[4096];
  ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  std::string beside = SMG_DEMO_DEFAULT_GRAPH;
  if (n > 0) {
    exe[n] = '\0';
    std::string dir(exe);
    size_t slash = dir.rfind('/');
    if (slash != std::string::npos) beside = dir.substr(0, slash + 1) + SMG_DEMO_DEFAULT_GRAPH;
  }
  std::string in_build = std::string("build/") + SMG_DEMO_DEFAULT_GRAPH;
  path = file_exists(beside) || !file_exists(in_build) ? beside : in_build;
  return path;
}

void usage(FILE* f) {
  std::fprintf(f,
               "usage: smg-demo [options]\n"
               "  --graph FILE        baked graph blob (default %s)\n"
               "  --characters N      characters on offset copies of the path (1..1000, default 1)\n"
               "  --script FILE       replay a drawing script (format: docs/demo.md)\n"
               "  --frames N          stop after N simulation frames\n"
               "  --screenshot FILE   render offscreen and write a PNG after --frames frames\n"
               "  --width W --height H  window / picture size (default 1280x720)\n"
               "  --dt SECONDS        fixed simulation step (default 1/60)\n"
               "  --no-hud            hide the ImGui panel\n"
               "  --help\n",
               default_graph().c_str());
}

// Returns 0 to continue, else an exit code (2 for usage errors).
int parse_options(int argc, char** argv, Options* o) {
  o->graph = default_graph();
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* what) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "smg-demo: %s needs a value\n", what);
        return nullptr;
      }
      return argv[++i];
    };
    auto int_value = [&](const char* what, int lo, int hi, int* out) -> bool {
      const char* v = value(what);
      if (!v) return false;
      if (!parse_int(v, out) || *out < lo || *out > hi) {
        std::fprintf(stderr, "smg-demo: %s must be an integer in %d..%d (got '%s')\n", what, lo, hi, v);
        return false;
      }
      return true;
    };
    if (a == "--help" || a == "-h") {
      usage(stdout);
      return -1;
    } else if (a == "--graph") {
      const char* v = value("--graph");
      if (!v) return 2;
      o->graph = v;
    } else if (a == "--script") {
      const char* v = value("--script");
      if (!v) return 2;
      o->script = v;
    } else if (a == "--screenshot") {
      const char* v = value("--screenshot");
      if (!v) return 2;
      o->screenshot = v;
    } else if (a == "--characters") {
      if (!int_value("--characters", 1, 1000, &o->characters)) return 2;
    } else if (a == "--frames") {
      if (!int_value("--frames", 0, 10000000, &o->frames)) return 2;
    } else if (a == "--width") {
      if (!int_value("--width", 16, 8192, &o->width)) return 2;
    } else if (a == "--height") {
      if (!int_value("--height", 16, 8192, &o->height)) return 2;
    } else if (a == "--dt") {
      const char* v = value("--dt");
      if (!v) return 2;
      if (!parse_float(v, &o->dt) || o->dt <= 0.0f || o->dt > 0.25f) {
        std::fprintf(stderr, "smg-demo: --dt must be a number in (0, 0.25] seconds (got '%s')\n", v);
        return 2;
      }
    } else if (a == "--no-hud") {
      o->hud = false;
    } else {
      std::fprintf(stderr, "smg-demo: unknown option '%s'\n", a.c_str());
      usage(stderr);
      return 2;
    }
  }
  if (!o->screenshot.empty() && o->frames < 0) {
    std::fprintf(stderr, "smg-demo: --screenshot needs --frames N\n");
    return 2;
  }
  return 0;
}

// Creates the window and an OpenGL 3.3 core context (multisampled when the
// driver allows it). Returns false with a message.
bool open_window(App& app, std::string* error) {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    *error = std::string("cannot initialise SDL video (is there a display? try xvfb-run): ") + SDL_GetError();
    return false;
  }
  const char* driver = SDL_GetCurrentVideoDriver();
  if (!app.headless && driver && (std::strcmp(driver, "offscreen") == 0 || std::strcmp(driver, "dummy") == 0)) {
    *error = std::string("no display to open a window on (SDL video driver '") + driver +
             "'); run it in a desktop session, or render pictures headless with --script/--frames/--screenshot";
    return false;
  }
  Uint32 flags = SDL_WINDOW_OPENGL | (app.headless ? SDL_WINDOW_HIDDEN : (SDL_WINDOW_RESIZABLE | SDL_WINDOW_SHOWN));
  for (int attempt = 0; attempt < 2 && !app.window; ++attempt) {
    bool msaa = attempt == 0 && !app.headless && !std::getenv("SMG_DEMO_NO_MSAA");  // offscreen has its own MSAA
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
    SDL_GL_SetAttribute(SDL_GL_STENCIL_SIZE, 8);
    SDL_GL_SetAttribute(SDL_GL_MULTISAMPLEBUFFERS, msaa ? 1 : 0);
    SDL_GL_SetAttribute(SDL_GL_MULTISAMPLESAMPLES, msaa ? 4 : 0);
    app.window = SDL_CreateWindow("libsmg demo - draw a path", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                  app.options.width, app.options.height, flags);
  }
  if (!app.window) {
    *error = std::string("cannot create an OpenGL window: ") + SDL_GetError();
    return false;
  }
  app.gl = SDL_GL_CreateContext(app.window);
  if (!app.gl) {
    *error = std::string("cannot create an OpenGL 3.3 core context: ") + SDL_GetError();
    return false;
  }
  if (!demo_gl_load(error)) return false;
  int major = 0, minor = 0;
  if (!demo_gl_version(&major, &minor) || major * 10 + minor < 33) {
    const GLubyte* v = glGetString(GL_VERSION);
    *error = std::string("OpenGL 3.3 or newer is required, this context is ") +
             (v ? reinterpret_cast<const char*>(v) : "unknown");
    return false;
  }
  SDL_GL_SetSwapInterval(app.headless ? 0 : 1);
  return true;
}

void close_window(App& app) {
  if (app.gl) SDL_GL_DeleteContext(app.gl);
  if (app.window) SDL_DestroyWindow(app.window);
  SDL_Quit();
}

void choose_tool_defaults(App& app) {
  // The transition tool starts on the second style (e.g. run) and the
  // splice tool on the first real action, so one click shows a change.
  app.tool_style = app.world.style_count() > 1 ? 1u : 0u;
  app.tool_action = app.world.action_count() > 1 ? 1u : 0u;
}

// Smooths a measurement for display (the HUD would flicker otherwise).
void ema(double* avg, double sample) { *avg = *avg == 0.0 ? sample : *avg * 0.9 + sample * 0.1; }

void simulate_one_frame(App& app, float dt) {
  app.world.step(dt);
  ema(&app.step_us_avg, app.world.step_us_avg());
  ema(&app.step_us_max, app.world.step_us_max());
  app.step_us_sum += app.world.step_us_avg();
  app.step_us_worst = std::max(app.step_us_worst, app.world.step_us_max());
  ++app.step_frames;
  if (app.camera.follow && !app.world.characters().empty()) {
    const float* p = app.world.characters()[0].state.position;
    app.camera.follow_towards(glm::vec3(p[0], 0.0f, p[2]), dt);
  }
  ++app.frame;
}

void render(App& app, int width, int height) {
  app.renderer.begin(width, height, app.camera);
  draw_scene(app.renderer, app.world, app.view);
  app.renderer.end();
  // Headless pictures render one frame only, but ImGui sizes auto-fit
  // windows on their first frame without drawing them: lay out once first.
  for (int pass = app.headless ? 0 : 1; pass < 2; ++pass) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    if (app.headless) {
      io.DisplaySize = ImVec2(float(width), float(height));
      io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    }
    ImGui::NewFrame();
    if (app.hud) draw_hud(app);
    ImGui::Render();
  }
  glViewport(0, 0, width, height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

int run_headless(App& app) {
  Offscreen target;
  std::string error;
  if (!target.create(app.options.width, app.options.height, &error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    return 1;
  }
  int status = 0;
  auto t0 = std::chrono::steady_clock::now();
  for (long f = 0; f < app.options.frames; ++f) {
    bool shot = false;
    std::string shot_path;
    if (!run_script_commands(app, &shot, &shot_path)) status = 1;
    simulate_one_frame(app, app.options.dt);
    if (shot) {
      target.bind();
      render(app, app.options.width, app.options.height);
      target.resolve();
      if (!save_framebuffer_png(shot_path, app.options.width, app.options.height, &error)) {
        std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
        status = 1;
      } else {
        std::printf("smg-demo: wrote %s (frame %ld)\n", shot_path.c_str(), app.frame);
      }
    }
    app.world.clear_error();
  }
  double sim_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  app.frame_ms = app.options.frames > 0 ? sim_ms / double(app.options.frames) : 0.0;
  target.bind();
  render(app, app.options.width, app.options.height);
  target.resolve();
  if (!save_framebuffer_png(app.options.screenshot, app.options.width, app.options.height, &error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    status = 1;
  } else {
    std::printf("smg-demo: wrote %s (%dx%d, %ld frames of %.4f s, %d characters, step+pose mean %.1f us/character, "
                "worst %.0f us)\n",
                app.options.screenshot.c_str(), app.options.width, app.options.height, app.frame,
                double(app.options.dt), int(app.world.characters().size()),
                app.step_frames ? app.step_us_sum / double(app.step_frames) : 0.0, app.step_us_worst);
  }
  // Where character 0's skeleton projects in the picture (pixels, origin
  // top-left): the smoke test checks that its body is drawn there.
  if (!app.world.characters().empty()) {
    float w = float(app.options.width), h = float(app.options.height);
    glm::mat4 vp = app.camera.projection(w / h) * app.camera.view();
    const std::vector<float>& m = app.world.characters()[0].matrices;
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (size_t j = 0; j < app.world.joint_count(); ++j) {
      glm::vec4 c = vp * glm::vec4(m[j * 16 + 12], m[j * 16 + 13], m[j * 16 + 14], 1.0f);
      if (c.w <= 0.0f) continue;
      glm::vec2 px((c.x / c.w * 0.5f + 0.5f) * w, (0.5f - c.y / c.w * 0.5f) * h);
      lo = glm::min(lo, px);
      hi = glm::max(hi, px);
    }
    if (lo.x <= hi.x)
      std::printf("smg-demo: character 0 skeleton box %.0f %.0f %.0f %.0f\n", double(lo.x), double(lo.y), double(hi.x),
                  double(hi.y));
  }
  // What the drawing ended as: lets tests check scripted mouse edits.
  std::printf("smg-demo: path %zu points, %.2f m; markers:", app.world.path().size(),
              double(app.world.path().length()));
  for (const Marker& m : app.world.markers()) {
    bool t = m.kind == MarkerKind::Transition;
    std::printf(" #%d %s %s @%.2f", m.uid, t ? "transition" : "splice",
                t ? app.world.style_name(m.value) : app.world.action_name(m.value), double(m.arc_length));
  }
  std::printf("%s\n", app.world.markers().empty() ? " none" : "");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  target.destroy();
  if (app.world.error_count() > 0) {
    std::fprintf(stderr, "smg-demo: %d runtime call(s) failed; last: %s\n", app.world.error_count(),
                 app.world.last_error().c_str());
  }
  return status;
}

int run_interactive(App& app) {
  using clock = std::chrono::steady_clock;
  auto last = clock::now();
  double accumulator = 0.0;
  int status = 0;
  int shot_index = 0;
  long rendered = 0;
  double frame_ms_sum = 0.0;
  while (!app.quit) {
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
      ImGui_ImplSDL2_ProcessEvent(&e);
      handle_event(app, e);
    }
    auto now = clock::now();
    double real = std::chrono::duration<double>(now - last).count();
    last = now;
    ema(&app.frame_ms, real * 1000.0);
    // Fixed-step simulation so scripts replay identically on screen and
    // headless; at most 4 steps per rendered frame when the machine lags.
    if (!app.paused) accumulator += real * double(app.speed);
    int steps = 0;
    while (accumulator >= double(app.options.dt) && steps < 4) {
      bool shot = false;
      std::string shot_path;
      if (!run_script_commands(app, &shot, &shot_path)) status = 1;
      simulate_one_frame(app, app.options.dt);
      accumulator -= double(app.options.dt);
      ++steps;
    }
    if (steps == 4) accumulator = 0.0;
    int w = 0, h = 0;
    SDL_GL_GetDrawableSize(app.window, &w, &h);
    if (w > 0 && h > 0) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      render(app, w, h);
      if (app.want_screenshot) {
        app.want_screenshot = false;
        std::string name = "smg-demo-" + std::to_string(++shot_index) + ".png", error;
        glReadBuffer(GL_BACK);
        if (save_framebuffer_png(name, w, h, &error)) app.status = "wrote " + name;
        else app.status = error;
      }
      SDL_GL_SwapWindow(app.window);
    } else {
      SDL_Delay(16);  // minimised
    }
    if (app.options.frames >= 0 && app.frame >= app.options.frames) app.quit = true;
    ++rendered;
    frame_ms_sum += real * 1000.0;
  }
  if (rendered > 0)
    std::printf("smg-demo: %ld rendered frames, mean frame %.2f ms, %d characters, step+pose mean %.1f us/character, "
                "worst %.0f us\n",
                rendered, frame_ms_sum / double(rendered), int(app.world.characters().size()),
                app.step_frames ? app.step_us_sum / double(app.step_frames) : 0.0, app.step_us_worst);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  App app;
  int rc = parse_options(argc, argv, &app.options);
  if (rc == -1) return 0;
  if (rc != 0) return rc;
  app.headless = !app.options.screenshot.empty();
  app.hud = app.options.hud;
  app.characters_wanted = app.options.characters;

  if (smg_version() != SMG_VERSION)
    std::fprintf(stderr, "smg-demo: warning: libsmg %06x linked, header is %06x\n", smg_version(), SMG_VERSION);

  std::string error;
  if (!app.options.script.empty() && !parse_script_file(app.options.script, &app.script, &error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    return 2;
  }
  // Load the data before opening a window: a bad file should not flash one.
  if (!app.world.load(app.options.graph, &error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    if (app.options.graph == default_graph())
      std::fprintf(stderr, "smg-demo: build the default graph with `make`, or pass --graph FILE\n");
    return 1;
  }
  choose_tool_defaults(app);
  if (!app.world.spawn(app.options.characters, &error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    return 1;
  }

  if (!open_window(app, &error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    close_window(app);
    return 1;
  }
  if (!app.renderer.init(&error)) {
    std::fprintf(stderr, "smg-demo: %s\n", error.c_str());
    close_window(app);
    return 1;
  }
  // Without a body the demo shows the capsule skeletons only.
  if (app.world.body().indices.empty()) {
    std::fprintf(stderr, "smg-demo: no skinned body, showing skeletons (%s)\n", app.world.body_error().c_str());
    app.view.show_skeleton = true;
  } else if (!app.renderer.set_body(app.world.body(), app.world.coarse_body(), &error)) {
    std::fprintf(stderr, "smg-demo: %s; showing skeletons\n", error.c_str());
    app.view.show_skeleton = true;
  }
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // never write imgui.ini into the caller's directory
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForOpenGL(app.window, app.gl);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status = app.headless ? run_headless(app) : run_interactive(app);
  if (app.script_errors) std::fprintf(stderr, "smg-demo: %d script command(s) failed\n", app.script_errors);

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
  app.renderer.shutdown();
  close_window(app);
  return status;
}
