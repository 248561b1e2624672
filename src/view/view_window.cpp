#include "view/view_window.hpp"

#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <dlfcn.h>
#include <imgui.h>
#include <link.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <deque>
#include <filesystem>
#include <iostream>
#include <span>
#include <stdexcept>
#include <string_view>

#include "core/errors.hpp"
#include "render/frame_recorder.hpp"
#include "render/frame_renderer.hpp"
#include "render/frame_scene.hpp"
#include "render/png_writer.hpp"
#include "view/screenshot_name.hpp"

namespace swarmagg {
namespace {

using Clock = std::chrono::steady_clock;

const char* const kHowToRun =
    "run it under a virtual display: xvfb-run -a -s '-screen 0 1280x1024x24' swarmagg view ... "
    "(Debian: apt-get install xvfb xauth)";

// The GL entry points the window itself calls, from the window's context.
struct WindowGl {
  decltype(&::glGenTextures) GenTextures = nullptr;
  decltype(&::glDeleteTextures) DeleteTextures = nullptr;
  decltype(&::glBindTexture) BindTexture = nullptr;
  decltype(&::glTexParameteri) TexParameteri = nullptr;
  decltype(&::glTexImage2D) TexImage2D = nullptr;
  decltype(&::glTexSubImage2D) TexSubImage2D = nullptr;
  decltype(&::glPixelStorei) PixelStorei = nullptr;
  decltype(&::glReadPixels) ReadPixels = nullptr;
  decltype(&::glReadBuffer) ReadBuffer = nullptr;
  decltype(&::glViewport) Viewport = nullptr;
  decltype(&::glFinish) Finish = nullptr;
  decltype(&::glClearColor) ClearColor = nullptr;
  decltype(&::glClear) Clear = nullptr;
  PFNGLGENFRAMEBUFFERSPROC GenFramebuffers = nullptr;
  PFNGLDELETEFRAMEBUFFERSPROC DeleteFramebuffers = nullptr;
  PFNGLBINDFRAMEBUFFERPROC BindFramebuffer = nullptr;
  PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus = nullptr;
  PFNGLFRAMEBUFFERRENDERBUFFERPROC FramebufferRenderbuffer = nullptr;
  PFNGLGENRENDERBUFFERSPROC GenRenderbuffers = nullptr;
  PFNGLDELETERENDERBUFFERSPROC DeleteRenderbuffers = nullptr;
  PFNGLBINDRENDERBUFFERPROC BindRenderbuffer = nullptr;
  PFNGLRENDERBUFFERSTORAGEPROC RenderbufferStorage = nullptr;
  PFNGLBLITFRAMEBUFFERPROC BlitFramebuffer = nullptr;

  template <class F>
  static void load(F& f, const char* name) {
    f = reinterpret_cast<F>(glfwGetProcAddress(name));
    if (f == nullptr) throw std::runtime_error(std::string("view: no OpenGL function ") + name);
  }
  void load_all() {
    load(GenTextures, "glGenTextures");
    load(DeleteTextures, "glDeleteTextures");
    load(BindTexture, "glBindTexture");
    load(TexParameteri, "glTexParameteri");
    load(TexImage2D, "glTexImage2D");
    load(TexSubImage2D, "glTexSubImage2D");
    load(PixelStorei, "glPixelStorei");
    load(ReadPixels, "glReadPixels");
    load(ReadBuffer, "glReadBuffer");
    load(Viewport, "glViewport");
    load(Finish, "glFinish");
    load(ClearColor, "glClearColor");
    load(Clear, "glClear");
    load(GenFramebuffers, "glGenFramebuffers");
    load(DeleteFramebuffers, "glDeleteFramebuffers");
    load(BindFramebuffer, "glBindFramebuffer");
    load(CheckFramebufferStatus, "glCheckFramebufferStatus");
    load(FramebufferRenderbuffer, "glFramebufferRenderbuffer");
    load(GenRenderbuffers, "glGenRenderbuffers");
    load(DeleteRenderbuffers, "glDeleteRenderbuffers");
    load(BindRenderbuffer, "glBindRenderbuffer");
    load(RenderbufferStorage, "glRenderbufferStorage");
    load(BlitFramebuffer, "glBlitFramebuffer");
  }
};

// Mesa's DRI driver (swrast_dri.so under Xvfb), opened by the GLX library, is closed again
// with the display, and global state it never frees becomes unreachable, which leak
// checkers report as a leak of ours. Held open for the process's life (as in any program
// that keeps its display), that state stays reachable. Called once a context exists.
void keep_gl_driver_loaded() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        const std::string_view path = info->dlpi_name != nullptr ? info->dlpi_name : "";
        if (path.ends_with("_dri.so"))
          ::dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}

// Keys (with the backends' callbacks chained by ImGui) and the mouse turn into commands and
// view changes here.
class Window {
 public:
  Window(ViewSession& session, const ViewWindowOptions& options);
  ~Window();
  void run();

 private:
  static Window& of(GLFWwindow* w) { return *static_cast<Window*>(glfwGetWindowUserPointer(w)); }
  void on_key(int key, int mods);
  void on_mouse_button(int button, int action);
  void on_cursor(double x, double y);
  void on_scroll(double dy);

  void push(ViewAction action) { queue_.push_back(view_command(action)); }
  void run_commands();
  void draw_scene();
  void show_frame();
  void draw_panel();
  void draw_noa_plot();
  void draw_inspector();
  void draw_tooltip();
  bool take_screenshot(const std::string& path);
  void make_frame_buffer();
  void finish_recording();      // says how many frames went where
  void copy_frame_to_window();  // false, with message_ saying why, on failure
  void set_recording(bool on);
  void record_step();
  FrameLayout fit_layout() const;
  FrameLayout view_layout() const;
  void pan_pixels(double dx, double dy);
  void zoom_at(double factor, double px, double py);
  void follow_selected();

  ViewSession& session_;
  GLFWwindow* window_ = nullptr;
  WindowGl gl_;
  int width_;
  int height_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::vector<std::uint8_t> pixels_;
  unsigned texture_ = 0;
  // The composed frame (scene and panel) at the frame's size, copied into the window.
  unsigned frame_buffer_ = 0;
  unsigned frame_colour_ = 0;
  std::deque<ViewCommand> queue_;
  std::deque<ViewCommand> script_;
  std::int64_t frame_limit_;
  // Seconds spent stepping, drawing the scene off-screen and in the window (upload, panel,
  // swap), over the frames so far.
  double step_total_ = 0, scene_total_ = 0, window_total_ = 0;
  double frame_seconds_ = 1.0 / 60.0;
  double fps_ = 0.0;
  double steps_per_second_ = 0.0;
  bool dragging_ = false;
  bool dragged_ = false;
  double press_x_ = 0, press_y_ = 0, last_x_ = 0, last_y_ = 0;
  double cursor_x_ = -1, cursor_y_ = -1;
  std::unique_ptr<FrameRecorder> recorder_;
  std::filesystem::path record_dir_;
  int record_every_ = 10;
  std::vector<std::uint8_t> record_pixels_;
  int typed_id_ = 0;
  std::string message_;
};

Window::Window(ViewSession& session, const ViewWindowOptions& options)
    : session_(session),
      width_(options.width),
      height_(options.height),
      script_(options.script.begin(), options.script.end()),
      frame_limit_(options.frames) {
  record_every_ =
      session.spec().render.every > 0 ? static_cast<int>(session.spec().render.every) : 10;
  record_dir_ = std::filesystem::path("renders") / (session.spec().name + "-view");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  const std::string title = "swarmagg view: " + session.spec().name;
  window_ = glfwCreateWindow(width_, height_, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    throw InputError(std::string("view: cannot open an OpenGL 3.3 window; ") + kHowToRun);
  }
  glfwSetWindowUserPointer(window_, this);
  // Installed before ImGui's, which call them after their own.
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action != GLFW_RELEASE) of(w).on_key(key, mods);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    of(w).on_mouse_button(button, action);
  });
  glfwSetCursorPosCallback(window_,
                           [](GLFWwindow* w, double x, double y) { of(w).on_cursor(x, y); });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) { of(w).on_scroll(dy); });
  glfwMakeContextCurrent(window_);
  keep_gl_driver_loaded();
  glfwSwapInterval(0);
  gl_.load_all();
  glfwGetFramebufferSize(window_, &width_, &height_);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the working folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330");

  gl_.GenTextures(1, &texture_);
  gl_.BindTexture(GL_TEXTURE_2D, texture_);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  make_frame_buffer();
  glfwMakeContextCurrent(nullptr);
  renderer_ = std::make_unique<FrameRenderer>(width_, height_);
  pixels_.resize(static_cast<std::size_t>(width_) * height_ * 4);
  session_.after_step = [this] { record_step(); };
}

Window::~Window() {
  session_.after_step = nullptr;
  // Quitting while recording ends the recording as R would, saying where the frames are.
  if (recorder_) {
    try {
      finish_recording();
    } catch (const std::exception& e) {
      std::cerr << "swarmagg: recording: " << e.what() << "\n";
    }
  }
  renderer_.reset();
  glfwMakeContextCurrent(window_);
  gl_.DeleteTextures(1, &texture_);
  gl_.DeleteFramebuffers(1, &frame_buffer_);
  gl_.DeleteRenderbuffers(1, &frame_colour_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
}

void Window::on_key(int key, int mods) {
  if (ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantCaptureKeyboard) return;
  const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
  const double pan = 0.1 * std::min(width_, height_);
  ViewCommand c;
  switch (key) {
    case GLFW_KEY_SPACE:
      push(ViewAction::TogglePlay);
      break;
    case GLFW_KEY_PERIOD:
      queue_.push_back(view_command(ViewAction::Step, 1));
      break;
    case GLFW_KEY_RIGHT:
      if (shift) {
        pan_pixels(-pan, 0);
      } else {
        queue_.push_back(view_command(ViewAction::Step, 1));
      }
      break;
    case GLFW_KEY_LEFT:
      pan_pixels(pan, 0);
      break;
    case GLFW_KEY_UP:
      pan_pixels(0, pan);
      break;
    case GLFW_KEY_DOWN:
      pan_pixels(0, -pan);
      break;
    case GLFW_KEY_R:
      push(shift ? ViewAction::Reseed : ViewAction::Reset);
      break;
    case GLFW_KEY_S:
      c.action = ViewAction::Screenshot;
      c.path = unused_screenshot_path(".", session_.spec().name, session_.replicate().steps_done())
                   .lexically_normal()
                   .string();
      queue_.push_back(c);
      break;
    case GLFW_KEY_V:
      queue_.push_back(record_command(!recorder_));
      break;
    case GLFW_KEY_TAB:
      session_.set_panel(!session_.panel());
      break;
    case GLFW_KEY_HOME:
      push(ViewAction::Fit);
      break;
    case GLFW_KEY_RIGHT_BRACKET:
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      session_.control().set_steps_per_frame(session_.control().steps_per_frame() * 2);
      break;
    case GLFW_KEY_LEFT_BRACKET:
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      session_.control().set_steps_per_frame(session_.control().steps_per_frame() / 2);
      break;
    case GLFW_KEY_X:
      session_.control().set_fastest();
      break;
    case GLFW_KEY_F:
      session_.follow = !session_.follow && session_.scene().selected >= 0;
      break;
    case GLFW_KEY_C:
      session_.scene().colour =
          static_cast<ColourMode>((static_cast<int>(session_.scene().colour) + 1) % 3);
      break;
    case GLFW_KEY_D:
      session_.scene().detection =
          static_cast<OverlayScope>((static_cast<int>(session_.scene().detection) + 2) % 3);
      break;
    case GLFW_KEY_A:
      session_.scene().approach =
          static_cast<OverlayScope>((static_cast<int>(session_.scene().approach) + 1) % 3);
      break;
    case GLFW_KEY_L:
      session_.scene().links = !session_.scene().links;
      break;
    case GLFW_KEY_N:
      session_.scene().neighbour_links = !session_.scene().neighbour_links;
      break;
    case GLFW_KEY_T:
      queue_.push_back(overlay_command(Overlay::Trails, !session_.scene().trails));
      break;
    case GLFW_KEY_G:
      session_.scene().ghosts = !session_.scene().ghosts;
      break;
    case GLFW_KEY_K:
      session_.scene().contacts = !session_.scene().contacts;
      break;
    case GLFW_KEY_ESCAPE:
      queue_.push_back(view_command(ViewAction::Select, -1));
      session_.follow = false;
      break;
    case GLFW_KEY_Q:
      push(ViewAction::Quit);
      break;
    default:
      break;
  }
}

void Window::on_mouse_button(int button, int action) {
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  if (action == GLFW_PRESS) {
    if (ImGui::GetIO().WantCaptureMouse) return;
    dragging_ = true;
    dragged_ = false;
    glfwGetCursorPos(window_, &press_x_, &press_y_);
    last_x_ = press_x_;
    last_y_ = press_y_;
  } else if (action == GLFW_RELEASE && dragging_) {
    dragging_ = false;
    if (!dragged_) {
      const std::int32_t agent =
          pick_agent(session_.snapshot(), view_layout(), Vec2{press_x_, press_y_});
      queue_.push_back(view_command(ViewAction::Select, agent));
    }
  }
}

void Window::on_cursor(double x, double y) {
  cursor_x_ = x;
  cursor_y_ = y;
  if (!dragging_) return;
  if (std::hypot(x - press_x_, y - press_y_) > 3.0) dragged_ = true;
  if (dragged_) {
    pan_pixels(x - last_x_, y - last_y_);
    session_.follow = false;
  }
  last_x_ = x;
  last_y_ = y;
}

void Window::on_scroll(double dy) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  zoom_at(std::pow(1.2, dy), cursor_x_, cursor_y_);
}

FrameLayout Window::fit_layout() const {
  return make_frame_layout(width_, height_, session_.spec().arena);
}

FrameLayout Window::view_layout() const {
  return FrameSceneBuilder::layout_for(fit_layout(), session_.scene());
}

// Moves the picture by (dx, dy) pixels.
void Window::pan_pixels(double dx, double dy) {
  const FrameLayout fit = fit_layout();
  SceneOptions& scene = session_.scene();
  const Vec2 centre = scene.centre.value_or(Vec2{fit.arena_width / 2, fit.arena_height / 2});
  const double scale = fit.scale * scene.zoom;
  scene.centre = Vec2{centre.x - dx / scale, centre.y + dy / scale};
}

// Zooms by `factor` keeping the arena point under the pixel (px, py) where it is.
void Window::zoom_at(double factor, double px, double py) {
  SceneOptions& scene = session_.scene();
  const FrameLayout before = view_layout();
  const FrameLayout fit = fit_layout();
  const Vec2 anchor = before.to_arena({px, py});
  const double zoom = std::clamp(scene.zoom * factor, 0.25, 500.0);
  const double scale = fit.scale * zoom;
  const PixelRect view = fit.view();
  const double cx = view.left + 0.5 * view.width;
  const double cy = view.top + 0.5 * view.height;
  scene.zoom = zoom;
  scene.centre = Vec2{anchor.x - (px - cx) / scale, anchor.y + (py - cy) / scale};
  if (std::abs(zoom - 1.0) < 1e-9) scene.zoom = 1.0;
}

void Window::follow_selected() {
  const std::int32_t selected = session_.scene().selected;
  if (!session_.follow || selected < 0) return;
  const auto details = session_.details(selected);
  if (details) session_.scene().centre = details->position;
}

void Window::run_commands() {
  if (!script_.empty()) {
    queue_.push_back(script_.front());
    script_.pop_front();
  }
  while (!queue_.empty() && !session_.quit_requested()) {
    const ViewCommand command = queue_.front();
    queue_.pop_front();
    try {
      session_.apply(command);
    } catch (const InputError& e) {
      if (!command.origin.empty()) throw InputError(command.origin + ": " + e.what());
      message_ = e.what();
      std::cerr << "swarmagg view: " << e.what() << "\n";
    }
    if (auto path = session_.take_screenshot_request()) {
      // Screenshots show the frame as drawn after the commands before them.
      draw_scene();
      show_frame();
      if (!take_screenshot(*path) && !command.origin.empty())
        throw std::runtime_error(command.origin + ": " + message_);
    }
    if (const auto record = session_.take_record_request()) set_recording(*record);
  }
}

void Window::finish_recording() {
  recorder_->finish();
  message_ = "recorded " + std::to_string(recorder_->frames_recorded()) + " frames into " +
             record_dir_.string() + "/ (swarmagg video " + record_dir_.string() + " OUT.mp4)";
  std::cout << message_ << std::endl;
  recorder_.reset();
}

// The scene, off-screen, into pixels_, with the window's context released.
void Window::draw_scene() {
  follow_selected();
  renderer_->render(session_.snapshot(), pixels_, session_.scene(), session_.extras());
}

void Window::set_recording(bool on) {
  if (on == static_cast<bool>(recorder_)) return;
  if (recorder_) {
    finish_recording();
    return;
  }
  WorldSpec spec = session_.spec();
  spec.render.width = width_;
  spec.render.height = height_;
  recorder_ = std::make_unique<FrameRecorder>(spec, record_dir_);
  message_ =
      "recording every " + std::to_string(record_every_) + " steps into " + record_dir_.string();
  record_step();
}

// After a step (and when recording starts): every record_every_-th step becomes a frame.
void Window::record_step() {
  if (!recorder_ || session_.replicate().steps_done() % record_every_ != 0) return;
  record_pixels_.resize(pixels_.size());
  follow_selected();
  renderer_->render(session_.snapshot(), record_pixels_, session_.scene(), session_.extras());
  recorder_->record_image(record_pixels_);
}

// pixels_ on screen, 1:1, the panel over it.
void Window::show_frame() {
  glfwMakeContextCurrent(window_);
  gl_.BindTexture(GL_TEXTURE_2D, texture_);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
  gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE,
                    pixels_.data());
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  // The panel is laid out on the frame, whatever size the window was given.
  ImGui::GetIO().DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
  ImGui::GetIO().DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  ImGui::NewFrame();
  ImGui::GetBackgroundDrawList()->AddImage(
      reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)), ImVec2(0, 0),
      ImVec2(static_cast<float>(width_), static_cast<float>(height_)));
  if (session_.panel()) {
    draw_panel();
    draw_tooltip();
  }
  ImGui::Render();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, frame_buffer_);
  gl_.Viewport(0, 0, width_, height_);  // no clear: the scene covers the whole frame
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  copy_frame_to_window();
}

// Frames are composed off-screen at the frame's size and copied into the window: a window
// resized anyway (a tiling window manager, xdotool) shows the same pixels, cropped or
// bordered, and a screenshot reads the composed frame, not whatever the window's buffer holds
// (it came out shifted and part blank).
void Window::make_frame_buffer() {
  gl_.GenRenderbuffers(1, &frame_colour_);
  gl_.BindRenderbuffer(GL_RENDERBUFFER, frame_colour_);
  gl_.RenderbufferStorage(GL_RENDERBUFFER, GL_RGB8, width_, height_);
  gl_.GenFramebuffers(1, &frame_buffer_);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, frame_buffer_);
  gl_.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, frame_colour_);
  const bool complete = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) throw std::runtime_error("view: cannot make an off-screen frame buffer");
}

// Pinned to the window's top-left corner, one pixel per pixel: where mouse positions count
// from, so that they stay on what they point at.
void Window::copy_frame_to_window() {
  int window_width = 0, window_height = 0;
  glfwGetFramebufferSize(window_, &window_width, &window_height);
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, frame_buffer_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  if (window_width != width_ || window_height != height_) {
    gl_.Viewport(0, 0, window_width, window_height);
    gl_.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl_.Clear(GL_COLOR_BUFFER_BIT);
  }
  gl_.BlitFramebuffer(0, 0, width_, height_, 0, window_height - height_, width_, window_height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool Window::take_screenshot(const std::string& path) {
  std::vector<std::uint8_t> rows(pixels_.size());
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, frame_buffer_);
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
  gl_.ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  std::vector<std::uint8_t> top_down(rows.size());
  const std::size_t stride = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    std::copy_n(rows.data() + (height_ - 1 - y) * stride, stride, top_down.data() + y * stride);
  }
  glfwMakeContextCurrent(nullptr);
  try {
    write_png(path, width_, height_, top_down, 1);
    message_ = "screenshot " + path;
    std::cout << "screenshot " << path << std::endl;
    return true;
  } catch (const std::exception& e) {
    message_ = std::string("screenshot failed: ") + e.what();
    std::cerr << "swarmagg view: " << message_ << "\n";
    return false;
  }
}

void Window::draw_panel() {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(300, 0),
                                      ImVec2(300, static_cast<float>(height_) - 16));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("swarmagg view (Tab hides)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  RunControl& control = session_.control();
  const Replicate& replicate = session_.replicate();
  if (ImGui::Button(control.playing() ? "Pause" : "Play")) push(ViewAction::TogglePlay);
  ImGui::SameLine();
  if (ImGui::Button("Step")) queue_.push_back(view_command(ViewAction::Step, 1));
  ImGui::SameLine();
  if (ImGui::Button("Reset")) push(ViewAction::Reset);
  ImGui::SameLine();
  if (ImGui::Button("Reseed")) push(ViewAction::Reseed);
  int pace = static_cast<int>(control.pace());
  ImGui::RadioButton("steps/frame", &pace, 0);
  ImGui::SameLine();
  ImGui::RadioButton("real time", &pace, 1);
  ImGui::SameLine();
  ImGui::RadioButton("fastest", &pace, 2);
  if (pace == 0) {
    int spf = static_cast<int>(control.steps_per_frame());
    if (ImGui::SliderInt("steps", &spf, 1, static_cast<int>(kMaxStepsPerFrame), "%d",
                         ImGuiSliderFlags_Logarithmic) ||
        control.pace() != Pace::StepsPerFrame) {
      control.set_steps_per_frame(spf);
    }
  } else if (pace == 1) {
    float factor = static_cast<float>(control.real_time_factor());
    if (ImGui::SliderFloat("x real time", &factor, 0.1f, 1000.0f, "%.1f",
                           ImGuiSliderFlags_Logarithmic) ||
        control.pace() != Pace::RealTime) {
      control.set_real_time(std::max(0.1f, factor));
    }
  } else if (control.pace() != Pace::Fastest) {
    control.set_fastest();
  }
  const std::vector<std::int32_t> counts = session_.state_counts();
  ImGui::Text("t %.1f  step %lld / %lld  NOA %d", replicate.time(),
              static_cast<long long>(replicate.steps_done()),
              static_cast<long long>(control.duration_steps()), replicate.aggregates().count());
  ImGui::Text("GO %d  WAIT %d  LEAVE %d  APPROACH %d", counts[0], counts[1], counts[2], counts[3]);
  ImGui::Text("%.0f steps/s  %.1f tu/s  %.0f fps", steps_per_second_,
              steps_per_second_ * session_.spec().engine.dt, fps_);
  draw_noa_plot();

  if (ImGui::CollapsingHeader("Colour and overlays")) {
    SceneOptions& scene = session_.scene();
    int colour = static_cast<int>(scene.colour);
    ImGui::RadioButton("state (C)", &colour, 0);
    ImGui::SameLine();
    ImGui::RadioButton("aggregate", &colour, 1);
    ImGui::SameLine();
    ImGui::RadioButton("size", &colour, 2);
    scene.colour = static_cast<ColourMode>(colour);
    const char* scopes[] = {"none", "selected", "all"};
    int detection = static_cast<int>(scene.detection);
    ImGui::Combo("detection (D)", &detection, scopes, 3);
    scene.detection = static_cast<OverlayScope>(detection);
    int approach = static_cast<int>(scene.approach);
    ImGui::Combo("approach (A)", &approach, scopes, 3);
    scene.approach = static_cast<OverlayScope>(approach);
    ImGui::Checkbox("aggregate links (L)", &scene.links);
    ImGui::SameLine();
    ImGui::Checkbox("tints", &scene.tints);
    ImGui::Checkbox("neighbour links (N)", &scene.neighbour_links);
    bool trails = scene.trails;
    if (ImGui::Checkbox("trails (T)", &trails)) {
      queue_.push_back(overlay_command(Overlay::Trails, trails));
    }
    ImGui::Checkbox("seam ghosts (G)", &scene.ghosts);
    ImGui::SameLine();
    ImGui::Checkbox("contacts (K)", &scene.contacts);
  }
  if (ImGui::CollapsingHeader("Inspect", ImGuiTreeNodeFlags_DefaultOpen)) draw_inspector();
  if (ImGui::CollapsingHeader("Capture")) {
    if (ImGui::Button("Screenshot (S)")) on_key(GLFW_KEY_S, 0);
    ImGui::SameLine();
    if (ImGui::Button(recorder_ ? "Stop recording (V)" : "Record (V)"))
      queue_.push_back(record_command(!recorder_));
    if (!recorder_) ImGui::InputInt("every k steps", &record_every_);
    record_every_ = std::max(1, record_every_);
  }
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
  ImGui::End();
}

// NOA over time (white) and the model's expected NOA (orange) where the world has a model.
void Window::draw_noa_plot() {
  const auto& history = session_.noa_history();
  const auto& model = session_.model_noa();
  const ImVec2 size(ImGui::GetContentRegionAvail().x, 80);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("noa-plot", size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                      IM_COL32(20, 20, 20, 255));
  // From t = 0 to now: the model's curve is cut at the current time.
  const double t_end = std::max(history.empty() ? 0.0 : history.back().time, 1.0);
  double noa_max = 1.0;
  for (const NoaPoint& p : history) noa_max = std::max(noa_max, p.noa);
  for (const NoaPoint& p : model) {
    if (p.time <= t_end) noa_max = std::max(noa_max, p.noa);
  }
  const auto at = [&](const NoaPoint& p) {
    return ImVec2(origin.x + static_cast<float>(p.time / t_end) * size.x,
                  origin.y + size.y - static_cast<float>(p.noa / noa_max) * (size.y - 4) - 2);
  };
  const auto polyline = [&](std::span<const NoaPoint> points, ImU32 colour) {
    // At most one vertex per horizontal pixel keeps long runs cheap to draw.
    const std::size_t stride =
        std::max<std::size_t>(1, points.size() / static_cast<std::size_t>(size.x + 1));
    for (std::size_t i = stride; i < points.size(); i += stride) {
      draw->AddLine(at(points[i - stride]), at(points[i]), colour, 1.5f);
    }
  };
  const auto model_end = std::upper_bound(model.begin(), model.end(), t_end,
                                          [](double t, const NoaPoint& p) { return t < p.time; });
  polyline(std::span<const NoaPoint>(model.begin(), model_end), IM_COL32(230, 159, 0, 255));
  polyline(history, IM_COL32(240, 240, 240, 255));
  draw->AddText(ImVec2(origin.x + 4, origin.y + 2), IM_COL32(200, 200, 200, 255),
                model.empty() ? "NOA" : "NOA (orange: model)");
}

void Window::draw_inspector() {
  SceneOptions& scene = session_.scene();
  if (scene.selected >= 0) typed_id_ = scene.selected;
  ImGui::SetNextItemWidth(130);
  if (ImGui::InputInt("agent id", &typed_id_, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue)) {
    queue_.push_back(view_command(ViewAction::Select, typed_id_));
  }
  ImGui::SameLine();
  ImGui::Checkbox("follow (F)", &session_.follow);
  const auto details = session_.details(scene.selected);
  if (!details) {
    ImGui::TextUnformatted("click an agent, or type its id");
    return;
  }
  const AgentDetails& d = *details;
  ImGui::Text("agent %d at (%.2f, %.2f) heading %.0f deg", d.id, d.position.x, d.position.y,
              std::atan2(d.heading.y, d.heading.x) * 180.0 / M_PI);
  ImGui::Text("%s for %.1f tu", std::string(to_string(d.state)).c_str(), d.time_in_state);
  if (d.last_transition) {
    ImGui::Text("last: %s -> %s at step %lld",
                std::string(to_string(d.last_transition->from)).c_str(),
                std::string(to_string(d.last_transition->to)).c_str(),
                static_cast<long long>(d.last_transition->step));
  }
  if (d.aggregate >= 0) {
    ImGui::Text("aggregate %d of %d agents", d.aggregate, d.aggregate_size);
  } else {
    ImGui::TextUnformatted("in no aggregate");
  }
  std::string neighbours;
  for (const std::uint32_t n : d.neighbours) neighbours += std::to_string(n) + " ";
  ImGui::TextWrapped("neighbours within s: %s", neighbours.empty() ? "none" : neighbours.c_str());
  if (d.approaching) ImGui::Text("approaching agent %u", *d.approaching);
}

void Window::draw_tooltip() {
  if (ImGui::GetIO().WantCaptureMouse || cursor_x_ < 0) return;
  const std::int32_t agent =
      pick_agent(session_.snapshot(), view_layout(), Vec2{cursor_x_, cursor_y_});
  const auto d = session_.details(agent);
  if (!d) return;
  ImGui::BeginTooltip();
  ImGui::Text("agent %d  %s  %.1f tu", d->id, std::string(to_string(d->state)).c_str(),
              d->time_in_state);
  if (d->aggregate >= 0) ImGui::Text("aggregate %d (%d agents)", d->aggregate, d->aggregate_size);
  ImGui::EndTooltip();
}

void Window::run() {
  const auto seconds = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto last = start;
  std::int64_t frames = 0;
  while (!glfwWindowShouldClose(window_) && !session_.quit_requested()) {
    glfwPollEvents();
    glfwMakeContextCurrent(nullptr);
    run_commands();
    if (session_.quit_requested()) break;
    const auto t0 = Clock::now();
    const std::int64_t steps = session_.advance_frame(frame_seconds_, 1.0 / 30.0);
    const auto t1 = Clock::now();
    draw_scene();
    const auto t2 = Clock::now();
    show_frame();
    glfwSwapBuffers(window_);
    const auto now = Clock::now();
    if (steps > 0 && seconds(t0, t1) > 0) steps_per_second_ = steps / seconds(t0, t1);
    step_total_ += seconds(t0, t1);
    scene_total_ += seconds(t1, t2);
    window_total_ += seconds(t2, now);
    frame_seconds_ = seconds(last, now);
    last = now;
    fps_ = fps_ == 0.0 ? 1.0 / frame_seconds_ : 0.9 * fps_ + 0.1 / frame_seconds_;
    if (++frames == frame_limit_) {
      const double total = seconds(start, now);
      const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
      std::printf(
          "view: %lld frames in %.2f s: %.1f fps; per frame %.2f ms stepping, %.2f ms drawing "
          "the scene, %.2f ms in the window; CPU of all this process's threads %.2f ms\n",
          static_cast<long long>(frames), total, frames / total, 1e3 * step_total_ / frames,
          1e3 * scene_total_ / frames, 1e3 * window_total_ / frames, 1e3 * cpu / frames);
      std::fflush(stdout);
      break;
    }
  }
  glfwMakeContextCurrent(nullptr);
}

}  // namespace

std::string display_problem() {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    return std::string("view: no display (DISPLAY is not set); ") + kHowToRun;
  }
  return {};
}

void run_view_window(ViewSession& session, const ViewWindowOptions& options) {
  if (const std::string problem = display_problem(); !problem.empty()) throw InputError(problem);
  glfwSetErrorCallback([](int, const char*) {});  // failures are reported below
  if (glfwInit() != GLFW_TRUE) {
    throw InputError(std::string("view: cannot open the display '") + std::getenv("DISPLAY") +
                     "'; " + kHowToRun);
  }
  struct Terminate {
    ~Terminate() { glfwTerminate(); }
  } terminate;
  Window window(session, options);
  window.run();
}

}  // namespace swarmagg
