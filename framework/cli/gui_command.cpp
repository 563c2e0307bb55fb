// lightlab gui [SCENE] [--preset FILE] [--assignment AN] [--[no-]watch] [--slides DECK.md [--slide N]]
//              [--[no-]projector] [--plot]
//              [--screenshot FILE --frames N]
#include <memory>

#include "cli/commands.h"
#include "gui/gui_app.h"

namespace ll::cli {

Command addGuiCommand(CLI::App& app, const GlobalOptions& global) {
  auto o = std::make_shared<gui::GuiOptions>();
  CLI::App* cmd = app.add_subcommand("gui", "Open the interactive window (panes, compare modes, presets)");
  cmd->add_option("scene", o->scene, "Scene file (.json or .obj); default: the Cornell box or the preset's scene");
  cmd->add_option("--preset", o->preset, "View preset (JSON) to open: scene, camera, panes, compare mode");
  cmd->add_option("--slides", o->slides,
                  "Presenter mode: this deck (slides/*.md) beside the panes; arrows, PageUp/PageDown, space step");
  cmd->add_option("--slide", o->slide, "With --slides: start at this slide (1-based)")->check(CLI::Range(1, 100000));
  cmd->add_option("--screenshot", o->screenshot,
                  "Save the window to this PNG (plus a .json sidecar) once every pane has finished, then exit");
  cmd->add_option("--frames", o->frames, "With --screenshot: draw at least this many UI frames first")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--timeout", o->screenshotTimeout, "With --screenshot: give up waiting after this many seconds")
      ->check(CLI::Range(1.0, 86400.0))
      ->capture_default_str();
  cmd->add_option("--window", o->windowWidth, "Window width in screen coordinates")->check(CLI::Range(320, 16384));
  cmd->add_option("--window-height", o->windowHeight, "Window height in screen coordinates")
      ->check(CLI::Range(240, 16384));
  cmd->add_option("--ui-scale", o->uiScale, "UI scale (times the monitor's content scale), e.g. 2 for projectors")
      ->check(CLI::Range(0.5, 4.0));
  cmd->add_option("--assignment", o->assignment,
                  "Focus on one assignment (A1 ... A6): its handout's scene and techniques running your code, "
                  "its tasks in the banners, every other task by its reference");
  cmd->add_flag_callback("--watch", [o] { o->watch = 1; },
                         "Rebuild and reload your code when you save a task's file (the default in the student tree)");
  cmd->add_flag_callback("--no-watch", [o] { o->watch = 0; }, "Do not rebuild on save");
  cmd->add_flag_callback("--projector", [o] { o->projector = 1; },
                         "Projector mode: one large label per pane naming what differs (P toggles; I shows the "
                         "stats; H hides the side panel); the default with --slides");
  cmd->add_flag_callback("--no-projector", [o] { o->projector = 0; }, "Full captions, also with --slides");
  cmd->add_flag_callback("--plot", [o] { o->plot = true; },
                         "Show the cost-of-accuracy plot: every pane's error against the reference pane over time");
  return [o, &global]() {
    (void)global;
    const int status = gui::runGui(*o);
    if (status != 0) throw CLI::RuntimeError(status);
  };
}

}  // namespace ll::cli
