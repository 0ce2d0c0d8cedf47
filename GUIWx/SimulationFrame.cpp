#include <GUIWx/ActivationPanel.h>
#include <GUIWx/SimulationFrame.h>
#include <GUIWx/ToolIcons.h>
#include <GUIWx/WorldView.h>

#include <wx/choice.h>
#include <wx/filedlg.h>
#include <wx/image.h>
#include <wx/menu.h>
#include <wx/msgdlg.h>
#include <wx/sizer.h>
#include <wx/stattext.h>
#include <wx/statusbr.h>
#include <wx/toolbar.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>

// wxWidgets owns its windows: a child window, menu or control is created with `new` and
// deleted by its parent (the frame, menu bar or toolbar). That is the one place raw `new`
// appears in Thyrix's code; everything Thyrix owns itself is held by value or unique_ptr.

namespace thyrix {
namespace {

enum : int {
  idRun = wxID_HIGHEST + 1,
  idStep,
  idReset,
  idFit,
  idScreenshot,
  idContacts,
  idForces,
  idTactile,
  idRays,
  idBaraff,
  idGaussSeidel,
  idSpeedChoice,
  idSolverChoice,
  idSpeed0,  // idSpeed0 + k: the k-th speed
};

constexpr double standardSpeeds[] = {10, 100, 1000, 0};

wxString speedLabel(double stepsPerSecond) {
  if (stepsPerSecond <= 0) return "As fast as possible";
  return wxString::Format("%g steps/s", stepsPerSecond);
}

const char* solverName(ContactSolverKind kind) {
  return kind == ContactSolverKind::Baraff ? "Baraff" : "Gauss-Seidel";
}

void printDragEvent(const DragEvent& e) {
  const auto x = static_cast<double>(e.position.x);
  const auto y = static_cast<double>(e.position.y);
  switch (e.kind) {
    case DragEvent::Kind::Start:
      std::printf("drag start %u %.4f %.4f grab %.4f %.4f step %" PRIu64 "\n", e.object, x, y,
                  static_cast<double>(e.target.x), static_cast<double>(e.target.y), e.step);
      break;
    case DragEvent::Kind::Move:
      std::printf("drag move %u %.4f %.4f target %.4f %.4f step %" PRIu64 "\n", e.object, x, y,
                  static_cast<double>(e.target.x), static_cast<double>(e.target.y), e.step);
      break;
    case DragEvent::Kind::End:
      std::printf("drag end %u %.4f %.4f step %" PRIu64 "\n", e.object, x, y, e.step);
      break;
    case DragEvent::Kind::Settled:
      std::printf("drag settled %u %.4f %.4f after %" PRIu64 " step %" PRIu64 "\n", e.object, x, y,
                  e.stepsSinceRelease, e.step);
      break;
  }
  std::fflush(stdout);  // a script reads these as they happen
}

}  // namespace

SimulationFrame::SimulationFrame(SimulationSetup setup, const GuiOptions& options,
                                 std::function<void(int)> exitCode)
    : wxFrame(nullptr, wxID_ANY, wxString::FromUTF8(setup.title), wxPoint(options.x, options.y),
              wxSize(options.width, options.height)),
      options_(options),
      exitCode_(std::move(exitCode)),
      automationTimer_(this) {
  if (wxImage::FindHandler(wxBITMAP_TYPE_PNG) == nullptr) wxImage::AddHandler(new wxPNGHandler);

  // The options override the application's defaults.
  if (options.stepsPerSecond)
    setup.stepsPerSecond = *options.stepsPerSecond;
  else if (!options.screenshot.empty())
    setup.stepsPerSecond = 0;  // a screenshot run has nothing to watch: as fast as possible
  if (options.paused) setup.startRunning = false;
  if (!options.screenshot.empty()) {
    setup.pauseAtStep = options.screenshotAfter;
    if (options.screenshotAfter == 0) setup.startRunning = false;
  } else if (options.stopAfter > 0) {
    setup.pauseAtStep = options.stopAfter;
  }
  draw_ = setup.drawOptions;
  const bool hasAgent = static_cast<bool>(setup.agentSignals);
  speeds_.assign(std::begin(standardSpeeds), std::end(standardSpeeds));
  if (std::find(speeds_.begin(), speeds_.end(), setup.stepsPerSecond) == speeds_.end())
    speeds_.insert(speeds_.end() - 1, setup.stepsPerSecond);
  runner_ = std::make_unique<SimulationRunner>(
      std::move(setup), options.printDrag ? SimulationRunner::DragListener(printDragEvent)
                                          : SimulationRunner::DragListener());

  auto* sizer = new wxBoxSizer(wxHORIZONTAL);
  view_ = new WorldView(this, *runner_);
  sizer->Add(view_, 1, wxEXPAND);
  if (hasAgent) {
    activity_ = new ActivationPanel(this);
    sizer->Add(activity_, 0, wxEXPAND);
  }
  SetSizer(sizer);

  buildMenus();
  buildToolBar();
  CreateStatusBar(4);
  const int widths[] = {-3, -2, -2, -3};
  SetStatusWidths(4, widths);

  // The single-key shortcuts. wxGTK does not bind menu accelerators without a modifier (they
  // would steal typing), and the focus may be on a toolbar control: catch them here, before
  // any window, whatever has the focus.
  Bind(wxEVT_CHAR_HOOK, &SimulationFrame::onKey, this);
  view_->setSnapshotListener([this](const WorldSnapshot& s) { onSnapshot(s); });
  Bind(wxEVT_CLOSE_WINDOW, [this](wxCloseEvent&) {
    shutDown();
    Destroy();
  });
  if (options_.printDrag || !options_.screenshot.empty()) {
    Bind(wxEVT_TIMER, &SimulationFrame::onAutomationTimer, this, automationTimer_.GetId());
    automationTimer_.Start(50);
  }
  view_->SetFocus();
}

SimulationFrame::~SimulationFrame() { shutDown(); }

void SimulationFrame::shutDown() {
  automationTimer_.Stop();
  // The view polls the runner: detach it before the runner (and its thread) goes.
  if (view_ != nullptr) view_->detach();
  runner_.reset();  // stops and joins the simulation thread
}

void SimulationFrame::buildMenus() {
  auto* file = new wxMenu;
  file->Append(idScreenshot, "Save &screenshot...\tCtrl+S", "Save a PNG picture of the view");
  file->AppendSeparator();
  file->Append(wxID_EXIT, "&Quit\tCtrl+Q");

  auto* speed = new wxMenu;
  for (std::size_t k = 0; k < speeds_.size(); ++k)
    speed->AppendRadioItem(idSpeed0 + static_cast<int>(k), speedLabel(speeds_[k]));
  auto* solver = new wxMenu;
  solver->AppendRadioItem(idBaraff, "&Baraff (pivoting, exact)");
  solver->AppendRadioItem(idGaussSeidel, "&Gauss-Seidel (iterative)");

  auto* simulation = new wxMenu;
  simulation->AppendCheckItem(idRun, "&Run\tSpace", "Run or pause the simulation");
  simulation->Append(idStep, "Single &step\tS", "Pause and advance one step");
  simulation->Append(idReset, "R&eset\tCtrl+R", "Rebuild the world from the start");
  simulation->AppendSeparator();
  simulation->AppendSubMenu(speed, "S&peed");
  simulation->AppendSubMenu(solver, "S&olver");

  auto* view = new wxMenu;
  view->AppendCheckItem(idContacts, "&Contacts\t1", "Contact points and normals");
  view->AppendCheckItem(idForces, "Contact &forces\t2", "Contact forces as lines");
  view->AppendCheckItem(idTactile, "&Tactile sensors\t3", "Tactile activations as dots");
  view->AppendCheckItem(idRays, "&Visual rays\t4", "The rays of the visual sensors");
  view->AppendSeparator();
  view->Append(idFit, "&Fit world to window\tF");

  auto* help = new wxMenu;
  help->Append(wxID_HELP, "&Controls");

  auto* bar = new wxMenuBar;
  bar->Append(file, "&File");
  bar->Append(simulation, "&Simulation");
  bar->Append(view, "&View");
  bar->Append(help, "&Help");
  SetMenuBar(bar);

  // Menu items and toolbar tools share their ids, so one handler serves both; their check
  // marks follow the state through update-UI events.
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { Close(); }, wxID_EXIT);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { saveScreenshotDialog(); }, idScreenshot);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { showControls(); }, wxID_HELP);
  Bind(
      wxEVT_MENU,
      [this](wxCommandEvent&) {
        if (runner_->running())
          runner_->pause();
        else
          runner_->run();
      },
      idRun);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { runner_->singleStep(); }, idStep);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { runner_->reset(); }, idReset);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { view_->fitWorld(); }, idFit);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { setSolver(ContactSolverKind::Baraff); }, idBaraff);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { setSolver(ContactSolverKind::GaussSeidel); },
      idGaussSeidel);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { toggleOverlay(&DrawOptions::contacts); }, idContacts);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { toggleOverlay(&DrawOptions::contactForces); },
      idForces);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { toggleOverlay(&DrawOptions::tactile); }, idTactile);
  Bind(
      wxEVT_MENU, [this](wxCommandEvent&) { toggleOverlay(&DrawOptions::visualRays); }, idRays);
  Bind(
      wxEVT_MENU,
      [this](wxCommandEvent& e) { setSpeed(static_cast<std::size_t>(e.GetId() - idSpeed0)); },
      idSpeed0, idSpeed0 + static_cast<int>(speeds_.size()) - 1);

  Bind(
      wxEVT_UPDATE_UI, [this](wxUpdateUIEvent& e) { e.Check(runner_ && runner_->running()); },
      idRun);
  const auto overlay = [this](int id, bool DrawOptions::*flag) {
    Bind(
        wxEVT_UPDATE_UI, [this, flag](wxUpdateUIEvent& e) { e.Check(draw_.*flag); }, id);
  };
  overlay(idContacts, &DrawOptions::contacts);
  overlay(idForces, &DrawOptions::contactForces);
  overlay(idTactile, &DrawOptions::tactile);
  overlay(idRays, &DrawOptions::visualRays);
  Bind(
      wxEVT_UPDATE_UI,
      [this](wxUpdateUIEvent& e) {
        if (runner_)
          e.Check(runner_->solver() == (e.GetId() == idBaraff ? ContactSolverKind::Baraff
                                                              : ContactSolverKind::GaussSeidel));
        // Only a Simulator has a contact solver.
        const WorldSnapshot* s = view_ != nullptr ? view_->snapshot().get() : nullptr;
        e.Enable(s == nullptr || s->isSimulator);
      },
      idBaraff, idGaussSeidel);
  Bind(
      wxEVT_UPDATE_UI,
      [this](wxUpdateUIEvent& e) {
        if (runner_)
          e.Check(speeds_[static_cast<std::size_t>(e.GetId() - idSpeed0)] ==
                  runner_->stepsPerSecond());
      },
      idSpeed0, idSpeed0 + static_cast<int>(speeds_.size()) - 1);
}

void SimulationFrame::buildToolBar() {
  wxToolBar* bar = CreateToolBar(wxTB_HORIZONTAL | wxTB_FLAT);
  bar->AddCheckTool(idRun, "Run", toolIcon(ToolIcon::Run), wxNullBitmap, "Run / pause (Space)");
  bar->AddTool(idStep, "Step", toolIcon(ToolIcon::Step), "Single step (S)");
  bar->AddTool(idReset, "Reset", toolIcon(ToolIcon::Reset), "Reset the world (Ctrl+R)");
  bar->AddSeparator();

  bar->AddControl(new wxStaticText(bar, wxID_ANY, " Speed "));
  speedChoice_ = new wxChoice(bar, idSpeedChoice);
  for (const double s : speeds_) speedChoice_->Append(speedLabel(s));
  bar->AddControl(speedChoice_);
  bar->AddControl(new wxStaticText(bar, wxID_ANY, "  Solver "));
  solverChoice_ = new wxChoice(bar, idSolverChoice);
  solverChoice_->Append("Baraff");
  solverChoice_->Append("Gauss-Seidel");
  bar->AddControl(solverChoice_);
  bar->AddSeparator();

  bar->AddCheckTool(idContacts, "Contacts", toolIcon(ToolIcon::Contacts), wxNullBitmap,
                    "Show contacts (1)");
  bar->AddCheckTool(idForces, "Forces", toolIcon(ToolIcon::Forces), wxNullBitmap,
                    "Show contact forces (2)");
  bar->AddCheckTool(idTactile, "Tactile", toolIcon(ToolIcon::Tactile), wxNullBitmap,
                    "Show tactile activations (3)");
  bar->AddCheckTool(idRays, "Rays", toolIcon(ToolIcon::Rays), wxNullBitmap, "Show visual rays (4)");
  bar->AddSeparator();
  bar->AddTool(idFit, "Fit", toolIcon(ToolIcon::Fit), "Fit the world to the window (F)");
  bar->AddTool(idScreenshot, "Screenshot", toolIcon(ToolIcon::Screenshot),
               "Save a screenshot (Ctrl+S)");
  bar->Realize();

  const double current = runner_->stepsPerSecond();
  for (std::size_t k = 0; k < speeds_.size(); ++k)
    if (speeds_[k] == current) speedChoice_->SetSelection(static_cast<int>(k));
  solverChoice_->SetSelection(runner_->solver() == ContactSolverKind::Baraff ? 0 : 1);
  speedChoice_->Bind(wxEVT_CHOICE, [this](wxCommandEvent& e) {
    if (e.GetSelection() >= 0) setSpeed(static_cast<std::size_t>(e.GetSelection()));
  });
  solverChoice_->Bind(wxEVT_CHOICE, [this](wxCommandEvent& e) {
    setSolver(e.GetSelection() == 0 ? ContactSolverKind::Baraff : ContactSolverKind::GaussSeidel);
  });
}

void SimulationFrame::onKey(wxKeyEvent& event) {
  if (event.HasAnyModifiers() || !runner_) {
    event.Skip();
    return;
  }
  switch (event.GetKeyCode()) {
    case WXK_SPACE:
      if (runner_->running())
        runner_->pause();
      else
        runner_->run();
      break;
    case 'S':
      runner_->singleStep();
      break;
    case 'F':
      view_->fitWorld();
      break;
    case '1':
      toggleOverlay(&DrawOptions::contacts);
      break;
    case '2':
      toggleOverlay(&DrawOptions::contactForces);
      break;
    case '3':
      toggleOverlay(&DrawOptions::tactile);
      break;
    case '4':
      toggleOverlay(&DrawOptions::visualRays);
      break;
    default:
      event.Skip();  // everything else goes on to the focused window
  }
}

void SimulationFrame::setSpeed(std::size_t index) {
  if (index >= speeds_.size()) return;
  runner_->setStepsPerSecond(speeds_[index]);
  speedChoice_->SetSelection(static_cast<int>(index));
}

void SimulationFrame::setSolver(ContactSolverKind solver) {
  runner_->setSolver(solver);
  solverChoice_->SetSelection(solver == ContactSolverKind::Baraff ? 0 : 1);
}

void SimulationFrame::toggleOverlay(bool DrawOptions::*overlay) {
  draw_.*overlay = !(draw_.*overlay);
  runner_->setDrawOptions(draw_);
}

void SimulationFrame::saveScreenshotDialog() {
  wxFileDialog dialog(this, "Save screenshot", "", "thyrix.png", "PNG files (*.png)|*.png",
                      wxFD_SAVE | wxFD_OVERWRITE_PROMPT);
  if (dialog.ShowModal() != wxID_OK) return;
  if (view_->saveScreenshot(dialog.GetPath()))
    SetStatusText("Saved " + dialog.GetPath(), 3);
  else
    wxMessageBox("Could not write " + dialog.GetPath(), "Save screenshot", wxOK | wxICON_ERROR,
                 this);
}

void SimulationFrame::showControls() {
  wxMessageBox(
      "Left-drag an object: pull it with the mouse force (released with the button).\n"
      "Mouse wheel: zoom about the cursor.   Right- or middle-drag: pan.\n"
      "F: fit the world to the window.   Space: run / pause.   S: single step.\n"
      "Ctrl+R: reset.   1-4: contacts, contact forces, tactile sensors, visual rays.\n"
      "Ctrl+S: save a screenshot (PNG).",
      "Controls", wxOK | wxICON_INFORMATION, this);
}

void SimulationFrame::onSnapshot(const WorldSnapshot& s) {
  if (activity_ != nullptr) activity_->setValues(s.sensors, s.effectors);
  // The status bar at most ten times a second: faster is unreadable and costs redraws.
  const auto now = std::chrono::steady_clock::now();
  if (s.running && now - lastStatus_ < std::chrono::milliseconds(100)) return;
  lastStatus_ = now;
  SetStatusText(wxString::Format("Step %" PRIu64 "  (%.2f s)", s.step, s.time), 0);
  SetStatusText(s.running ? wxString::Format("%.0f steps/s", s.stepsPerSecond) : wxString("Paused"),
                1);
  // A world that is not a Simulator has no contacts and no solver: its fields stay empty.
  SetStatusText(s.isSimulator ? wxString::Format("%zu contacts", s.contacts) : wxString(), 2);
  SetStatusText(!s.error.empty() ? wxString::FromUTF8(s.error)
                : s.isSimulator  ? wxString(solverName(s.solver))
                                 : wxString(),
                3);
  if (solverChoice_->IsEnabled() != s.isSimulator) solverChoice_->Enable(s.isSimulator);
}

void SimulationFrame::onAutomationTimer(wxTimerEvent&) {
  if (finished_ || !runner_) return;
  const std::shared_ptr<const WorldSnapshot>& s = view_->snapshot();
  if (!s) return;
  if (!s->error.empty()) {
    std::fprintf(stderr, "%s\n", s->error.c_str());
    finishAutomation(1);
    return;
  }
  if (!view_->ready() || !view_->IsShownOnScreen()) return;
  if (options_.printDrag) {
    // Wait a moment after the window first shows: the window system may still be placing it,
    // and the screen pixels printed must be where the objects really are.
    const auto now = std::chrono::steady_clock::now();
    if (!readySeen_) {
      readySeen_ = true;
      readySince_ = now;
    }
    if (now - readySince_ >= std::chrono::milliseconds(300)) printLayout(*s);
  }
  if (!options_.screenshot.empty() && s->step >= options_.screenshotAfter && !s->running) {
    const bool saved = view_->saveScreenshot(wxString::FromUTF8(options_.screenshot));
    if (saved) {
      const ViewTransform& t = view_->transform();
      std::printf("screenshot %s %d %d scale %.6f centre %.6f %.6f step %" PRIu64 "\n",
                  options_.screenshot.c_str(), t.width(), t.height(), t.scale(),
                  static_cast<double>(t.centre().x), static_cast<double>(t.centre().y), s->step);
      for (const PickShape& shape : s->shapes) {
        const Vector2 c = (shape.a + shape.b) * real(0.5);
        std::printf("object %u %s %.4f %.4f %.4f\n", shape.object,
                    shape.type == ShapeType::Circle ? "circle" : "capsule",
                    static_cast<double>(c.x), static_cast<double>(c.y),
                    static_cast<double>(shape.radius));
      }
      std::fflush(stdout);
    } else {
      std::fprintf(stderr, "could not write the screenshot %s\n", options_.screenshot.c_str());
    }
    finishAutomation(saved ? 0 : 1);
  }
}

void SimulationFrame::printLayout(const WorldSnapshot& s) {
  const ViewTransform& t = view_->transform();
  const wxPoint origin = view_->ClientToScreen(wxPoint(0, 0));
  char line[256];
  std::snprintf(line, sizeof line, "view %d %d %d %d scale %.6f centre %.6f %.6f", origin.x,
                origin.y, t.width(), t.height(), t.scale(), static_cast<double>(t.centre().x),
                static_cast<double>(t.centre().y));
  if (line == lastViewLine_) return;  // printed already, and nothing moved since
  lastViewLine_ = line;
  std::printf("%s\n", line);
  if (!layoutPrinted_) {
    layoutPrinted_ = true;
    for (const PickShape& shape : s.shapes) {
      const Vector2 c = (shape.a + shape.b) * real(0.5);
      const PixelPoint p = t.toPixel(c);
      std::printf("object %u %s %.4f %.4f %.4f pixel %ld %ld\n", shape.object,
                  shape.type == ShapeType::Circle ? "circle" : "capsule", static_cast<double>(c.x),
                  static_cast<double>(c.y), static_cast<double>(shape.radius),
                  std::lround(origin.x + p.x), std::lround(origin.y + p.y));
    }
    std::printf("ready\n");
  }
  std::fflush(stdout);
}

void SimulationFrame::finishAutomation(int code) {
  finished_ = true;
  if (exitCode_) exitCode_(code);
  Close(true);
}

}  // namespace thyrix
