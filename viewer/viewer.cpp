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

// Opens the window with its GL context, ImGui and the picture's texture; false without a display.
bool open_window(Window& window, const std::string& title, int width, int height, bool vsync) {
  window.handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window.handle) return false;
  glfwMakeContextCurrent(window.handle);
  pin_loaded_libraries();
  glfwSwapInterval(vsync ? 1 : 0);
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
  return true;
}

// What is on screen: a saved run's frames or a live scene, the camera, the colouring, and
// whether time is moving. One tick of the window's loop: advance, panel, camera, picture.
class ViewLoop {
 public:
  ViewLoop(RunFrames* run, LiveScene* live, const ViewOptions& options, int width, int height)
      : run_(run),
        live_(live),
        facts_(run ? run->facts() : live->facts()),
        height_(height),
        orbit_(facts_.settings.camera ? *facts_.settings.camera
                                      : render::camera_for_particles(frame().particles, facts_.up,
                                                                     double(width) / height)) {
    context_.settings = facts_.settings;
    context_.settings.samples_per_axis = 1;
    context_.title = facts_.name;
    context_.threads = options.threads;
    context_.particle_spacing = facts_.spacing.value_or(0.02);
    colour_by_ = facts_.settings.color_by;
    if (!render::frame_has_field(frame().particles, colour_by_) && colour_by_ != "type" &&
        colour_by_ != "material")
      colour_by_ = "type";
    playing_ = options.play;
    if (live_ && live_->edited().output.fps > 0) frame_seconds_ = 1.0 / live_->edited().output.fps;
  }

  const ViewFacts& facts() const { return facts_; }

  // Time moves on first, so the panel's statistics describe the picture drawn after it.
  void advance() {
    if (!playing_ && !step_) return;
    if (run_) {
      if (run_->index() + 1 < run_->count()) {
        run_->show(run_->index() + 1);
        dirty_ = true;
      } else {
        playing_ = false;
      }
    } else {
      live_->advance(step_ ? 0 : frame_seconds_, step_ ? 0 : 0.1);
      if (!live_->error().empty()) playing_ = false;
      dirty_ = true;
    }
    step_ = false;
  }

  // The control panel, below the picture's title and time (top left).
  void panel() {
    ImGui::SetNextWindowPos(ImVec2(10, 50), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("upf view");
    ImGui::Text("%s (%s)", facts_.name.c_str(), run_ ? "saved run" : "live scene");
    if (ImGui::Button(playing_ ? "Pause" : "Play")) playing_ = !playing_;
    ImGui::SameLine();
    if (ImGui::Button("Step")) {
      step_ = true;
      playing_ = false;
    }
    if (run_) {
      int k = run_->index();
      if (ImGui::SliderInt("frame", &k, 0, run_->count() - 1) && k != run_->index()) {
        run_->show(k);
        playing_ = false;
        dirty_ = true;
      }
    }
    look_choices();
    ImGui::Separator();
    statistics();
    if (live_ && parameter_panel(*live_)) {
      live_->restart();
      playing_ = false;
      dirty_ = true;
    }
    ImGui::TextDisabled("left-drag: rotate, right-drag: pan, wheel: zoom");
    ImGui::End();
  }

  // The camera, when the panel does not want the mouse.
  void camera_input(const ImGuiIO& io) {
    if (io.WantCaptureMouse) return;
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
      orbit_.rotate(io.MouseDelta.x, io.MouseDelta.y);
      dirty_ = true;
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
      orbit_.pan(io.MouseDelta.x, io.MouseDelta.y, picture_h_ > 0 ? picture_h_ : height_);
      dirty_ = true;
    }
    if (io.MouseWheel != 0) {
      orbit_.zoom(io.MouseWheel);
      dirty_ = true;
    }
  }

  // The picture, ray traced at the framebuffer's size into `texture` whenever something changed.
  void refresh_picture(GLuint texture, int fb_w, int fb_h) {
    if (fb_w <= 0 || fb_h <= 0 || (!dirty_ && fb_w == picture_w_ && fb_h == picture_h_)) return;
    context_.camera = orbit_.camera();
    context_.scale = frame_scale(frame().particles, colour_by_);
    // The scene's own range, when it sets one for the field it colours by, as upf render does.
    if (context_.scale && facts_.settings.range && colour_by_ == facts_.settings.color_by) {
      context_.scale->low = (*facts_.settings.range)[0];
      context_.scale->high = (*facts_.settings.range)[1];
    }
    const render::Image picture = render::draw_frame(frame(), context_);
    const std::vector<std::uint8_t> rgb = picture.rgb8();
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, picture.width(), picture.height(), 0, GL_RGB,
                 GL_UNSIGNED_BYTE, rgb.data());
    picture_w_ = fb_w;
    picture_h_ = fb_h;
    dirty_ = false;
  }

 private:
  const render::FrameData& frame() const { return run_ ? run_->frame() : live_->frame(); }

  // Which field colours the particles, how walls are drawn, and the liquid as water.
  void look_choices() {
    const std::vector<std::string> choices = render::colour_choices(frame().particles);
    if (ImGui::BeginCombo("colour by", colour_by_.c_str())) {
      for (const std::string& c : choices)
        if (ImGui::Selectable(c.c_str(), c == colour_by_)) {
          colour_by_ = c;
          dirty_ = true;
        }
      ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("walls", render::wall_style_name(context_.settings.walls))) {
      for (auto w : {render::WallStyle::Glass, render::WallStyle::Solid, render::WallStyle::Hidden})
        if (ImGui::Selectable(render::wall_style_name(w), w == context_.settings.walls)) {
          context_.settings.walls = w;
          dirty_ = true;
        }
      ImGui::EndCombo();
    }
    // A saved run's "surface" frames: the liquid as water (render --surface).
    if (render::has_liquid_surface(frame()) &&
        ImGui::Checkbox("water surface", &context_.settings.surface))
      dirty_ = true;
  }

  // The frame shown, or the live world's last step; a live scene's error in red.
  void statistics() {
    if (run_) {
      ImGui::Text("frame %d of %d, t = %.4f s", run_->index() + 1, run_->count(), frame().time);
    } else if (const World* world = live_->world()) {
      const StepReport& r = world->last_step();
      ImGui::Text("t = %.4f s, step %llu, dt = %.3g s", world->time(),
                  static_cast<unsigned long long>(world->step_count()), r.dt);
      ImGui::Text("solver iterations %d", r.solver.iterations);
      ImGui::Text("density error avg %.3g %%, max %.3g %%", 100 * r.solver.avg_density_error,
                  100 * r.solver.max_density_error);
      ImGui::Text("%zu particles", world->particles().size());
    }
    if (live_ && !live_->error().empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.35f, 0.35f, 1));
      ImGui::TextWrapped("%s", live_->error().c_str());
      ImGui::PopStyleColor();
    }
  }

  RunFrames* run_;
  LiveScene* live_;
  const ViewFacts& facts_;
  int height_;
  render::PictureContext context_;
  OrbitCamera orbit_;
  std::string colour_by_;
  bool playing_ = false, dirty_ = true;
  bool step_ = false;  // the Step button of the previous tick
  int picture_w_ = 0, picture_h_ = 0;
  double frame_seconds_ = 1.0 / 30;  // simulated time per tick of a live scene
};

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
  const std::string name = run ? run->facts().name : live->facts().name;

  glfwSetErrorCallback([](int, const char* what) { std::fprintf(stderr, "glfw: %s\n", what); });
  Window window;
  if (!glfwInit() || !open_window(window, "upf view: " + name, width, height, exit_after == 0)) {
    std::fprintf(stderr, "error: %s\n", no_display_message().c_str());
    return 1;
  }
  ViewLoop view(run.get(), live.get(), options, width, height);
  for (int drawn = 1; !glfwWindowShouldClose(window.handle); ++drawn) {
    glfwPollEvents();
    view.advance();
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    view.panel();
    view.camera_input(io);
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window.handle, &fb_w, &fb_h);
    view.refresh_picture(window.texture, fb_w, fb_h);
    ImGui::GetBackgroundDrawList()->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(window.texture)), ImVec2(0, 0),
        io.DisplaySize);

    ImGui::Render();
    glViewport(0, 0, fb_w, fb_h);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
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
