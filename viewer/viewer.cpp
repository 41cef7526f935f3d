#include "viewer/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl2.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/errors.h"
#include "render/image.h"
#include "viewer/frame_scale.h"
#include "viewer/orbit_camera.h"
#include "viewer/pin_loaded_libraries.h"
#include "viewer/view_source.h"

namespace upf::viewer {

namespace fs = std::filesystem;

namespace {

// The window's pixels (the back buffer, before it is swapped), top row first.
render::Image read_back(int width, int height) {
  std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  render::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t k = 3 * (std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x));
      image.at(x, y) = render::Colour(float(rgb[k]) / 255.f, float(rgb[k + 1]) / 255.f,
                                      float(rgb[k + 2]) / 255.f);
    }
  return image;
}

// The window, the ImGui context and the picture's texture, released in reverse order.
struct Window {
  GLFWwindow* handle = nullptr;
  bool imgui = false;
  GLuint texture = 0;
  ~Window() {
    if (texture) glDeleteTextures(1, &texture);
    if (imgui) {
      ImGui_ImplOpenGL2_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
    if (handle) glfwDestroyWindow(handle);
    glfwTerminate();
  }
};

// The solver parameters of a live scene's materials, editable, clamped to their ranges.
// Returns true when "Apply and restart" was pressed.
bool parameter_panel(LiveScene& live) {
  bool apply = false;
  if (!ImGui::CollapsingHeader("Solver parameters")) return false;
  ImGui::TextWrapped("Changes take effect when applied: the run restarts from t = 0.");
  for (Material& m : live.edited().materials) {
    if (m.solver.empty()) continue;
    const SolverInfo* info = live.registry().find_solver(m.solver);
    if (!info) continue;
    ImGui::PushID(m.name.c_str());
    ImGui::Text("%s (%s)", m.name.c_str(), m.solver.c_str());
    for (const ParamSpec& spec : info->params) {
      if (!m.solver_params.has(spec.name)) continue;
      double value = m.solver_params.get(spec.name);
      const std::string label = spec.name + " [" + spec.unit + "]";
      bool changed = false;
      if (spec.integer) {
        int v = int(value);
        changed = ImGui::InputInt(label.c_str(), &v);
        value = v;
      } else {
        changed = ImGui::InputDouble(label.c_str(), &value, 0, 0, "%.6g");
      }
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s\nrange [%g, %g], default %g", spec.description.c_str(),
                          spec.min_value, spec.max_value, spec.default_value);
      if (changed)
        m.solver_params.set(spec.name, std::clamp(value, spec.min_value, spec.max_value));
    }
    ImGui::PopID();
  }
  apply = ImGui::Button("Apply and restart");
  return apply;
}

}  // namespace

std::string no_display_message() {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    return "upf view needs a display (DISPLAY is not set); run it under xvfb-run or use upf render";
  return std::string("upf view needs a display (cannot open DISPLAY=") + display +
         "); run it under xvfb-run or use upf render";
}

int run_viewer(const ViewOptions& options, const Registry& registry) {
  const auto [width, height] = render::parse_picture_size(options.size, "--size");
  if (options.exit_after < 0) throw InputError("--exit-after", "expected a whole number >= 1");
  const int exit_after =
      options.exit_after > 0 ? options.exit_after : (options.screenshot.empty() ? 0 : 3);

  // The input first: a bad one is exit code 2 with or without a display.
  std::unique_ptr<RunFrames> run;
  std::unique_ptr<LiveScene> live;
  if (fs::is_directory(options.input))
    run = std::make_unique<RunFrames>(options.input);
  else
    live = std::make_unique<LiveScene>(options.input, registry, options.threads);
  const ViewFacts& facts = run ? run->facts() : live->facts();
  auto frame = [&]() -> const render::FrameData& { return run ? run->frame() : live->frame(); };

  glfwSetErrorCallback([](int, const char* what) { std::fprintf(stderr, "glfw: %s\n", what); });
  if (!glfwInit()) {
    std::fprintf(stderr, "error: %s\n", no_display_message().c_str());
    return 1;
  }
  Window window;
  const std::string title = "upf view: " + facts.name;
  window.handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window.handle) {
    std::fprintf(stderr, "error: %s\n", no_display_message().c_str());
    return 1;
  }
  glfwMakeContextCurrent(window.handle);
  pin_loaded_libraries();
  glfwSwapInterval(exit_after > 0 ? 0 : 1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window.handle, true);
  ImGui_ImplOpenGL2_Init();
  window.imgui = true;
  glGenTextures(1, &window.texture);
  glBindTexture(GL_TEXTURE_2D, window.texture);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  render::PictureContext context;
  context.settings = facts.settings;
  context.settings.samples_per_axis = 1;
  context.title = facts.name;
  context.threads = options.threads;
  context.particle_spacing = facts.spacing.value_or(0.02);
  OrbitCamera orbit(
      facts.settings.camera
          ? *facts.settings.camera
          : render::camera_for_particles(frame().particles, facts.up, double(width) / height));
  std::string colour_by = facts.settings.color_by;
  if (!render::frame_has_field(frame().particles, colour_by) && colour_by != "type" &&
      colour_by != "material")
    colour_by = "type";

  bool playing = options.play, dirty = true;
  int drawn = 0, picture_w = 0, picture_h = 0;
  double frame_seconds = 1.0 / 30;  // simulated time per tick of a live scene
  if (live && live->edited().output.fps > 0) frame_seconds = 1.0 / live->edited().output.fps;

  bool step = false;  // the Step button of the previous tick
  while (!glfwWindowShouldClose(window.handle)) {
    glfwPollEvents();

    // Time moves on first, so the panel's statistics describe the picture drawn below.
    if (playing || step) {
      if (run) {
        if (run->index() + 1 < run->count()) {
          run->show(run->index() + 1);
          dirty = true;
        } else {
          playing = false;
        }
      } else {
        live->advance(step ? 0 : frame_seconds, step ? 0 : 0.1);
        if (!live->error().empty()) playing = false;
        dirty = true;
      }
      step = false;
    }

    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGuiIO& io = ImGui::GetIO();

    // Below the picture's title and time (top left).
    ImGui::SetNextWindowPos(ImVec2(10, 50), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("upf view");
    ImGui::Text("%s (%s)", facts.name.c_str(), run ? "saved run" : "live scene");
    if (ImGui::Button(playing ? "Pause" : "Play")) playing = !playing;
    ImGui::SameLine();
    if (ImGui::Button("Step")) {
      step = true;
      playing = false;
    }
    if (run) {
      int k = run->index();
      if (ImGui::SliderInt("frame", &k, 0, run->count() - 1) && k != run->index()) {
        run->show(k);
        playing = false;
        dirty = true;
      }
    }
    const std::vector<std::string> choices = render::colour_choices(frame().particles);
    if (ImGui::BeginCombo("colour by", colour_by.c_str())) {
      for (const std::string& c : choices)
        if (ImGui::Selectable(c.c_str(), c == colour_by)) {
          colour_by = c;
          dirty = true;
        }
      ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("walls", render::wall_style_name(context.settings.walls))) {
      for (auto w : {render::WallStyle::Glass, render::WallStyle::Solid, render::WallStyle::Hidden})
        if (ImGui::Selectable(render::wall_style_name(w), w == context.settings.walls)) {
          context.settings.walls = w;
          dirty = true;
        }
      ImGui::EndCombo();
    }
    ImGui::Separator();
    if (run) {
      ImGui::Text("frame %d of %d, t = %.4f s", run->index() + 1, run->count(), frame().time);
    } else if (const World* world = live->world()) {
      const StepReport& r = world->last_step();
      ImGui::Text("t = %.4f s, step %llu, dt = %.3g s", world->time(),
                  static_cast<unsigned long long>(world->step_count()), r.dt);
      ImGui::Text("solver iterations %d", r.solver.iterations);
      ImGui::Text("density error avg %.3g %%, max %.3g %%", 100 * r.solver.avg_density_error,
                  100 * r.solver.max_density_error);
      ImGui::Text("%zu particles", world->particles().size());
    }
    if (live && !live->error().empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.35f, 0.35f, 1));
      ImGui::TextWrapped("%s", live->error().c_str());
      ImGui::PopStyleColor();
    }
    if (live && parameter_panel(*live)) {
      live->restart();
      playing = false;
      dirty = true;
    }
    ImGui::TextDisabled("left-drag: rotate, right-drag: pan, wheel: zoom");
    ImGui::End();

    // The camera, when the panel does not want the mouse.
    if (!io.WantCaptureMouse) {
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
        orbit.rotate(io.MouseDelta.x, io.MouseDelta.y);
        dirty = true;
      }
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
        orbit.pan(io.MouseDelta.x, io.MouseDelta.y, picture_h > 0 ? picture_h : height);
        dirty = true;
      }
      if (io.MouseWheel != 0) {
        orbit.zoom(io.MouseWheel);
        dirty = true;
      }
    }

    // The picture: ray traced at the framebuffer's size whenever something changed.
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window.handle, &fb_w, &fb_h);
    if (fb_w > 0 && fb_h > 0 && (dirty || fb_w != picture_w || fb_h != picture_h)) {
      context.camera = orbit.camera();
      context.scale = frame_scale(frame().particles, colour_by);
      // The scene's own range, when it sets one for the field it colours by, as upf render does.
      if (context.scale && facts.settings.range && colour_by == facts.settings.color_by) {
        context.scale->low = (*facts.settings.range)[0];
        context.scale->high = (*facts.settings.range)[1];
      }
      const render::Image picture = render::draw_frame(frame(), context);
      const std::vector<std::uint8_t> rgb = picture.rgb8();
      glBindTexture(GL_TEXTURE_2D, window.texture);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, picture.width(), picture.height(), 0, GL_RGB,
                   GL_UNSIGNED_BYTE, rgb.data());
      picture_w = fb_w;
      picture_h = fb_h;
      dirty = false;
    }
    ImGui::GetBackgroundDrawList()->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(window.texture)), ImVec2(0, 0),
        io.DisplaySize);

    ImGui::Render();
    glViewport(0, 0, fb_w, fb_h);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    ++drawn;
    if (exit_after > 0 && drawn >= exit_after) {
      if (!options.screenshot.empty()) {
        glFinish();
        render::write_png(options.screenshot, read_back(fb_w, fb_h));
      }
      break;
    }
    glfwSwapBuffers(window.handle);
  }
  return 0;
}

}  // namespace upf::viewer
