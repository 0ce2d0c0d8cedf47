#include <GUIWx/SimulationApp.h>
#include <GUIWx/SimulationFrame.h>

#include <wx/app.h>
#include <wx/init.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <string>

namespace thyrix {
namespace {

void printAssert(const wxString& file, int line, const wxString& function, const wxString& cond,
                 const wxString& message) {
  std::fprintf(stderr, "wxWidgets assertion failed: %s:%d %s: %s %s\n",
               static_cast<const char*>(file.utf8_str()), line,
               static_cast<const char*>(function.utf8_str()),
               static_cast<const char*>(cond.utf8_str()),
               static_cast<const char*>(message.utf8_str()));
}

void closeTopWindow(int) {
  if (wxTheApp == nullptr) return;
  if (wxWindow* top = wxTheApp->GetTopWindow(); top != nullptr) top->Close(true);
  // The window is deleted, and the main loop ends, at the next idle time; nothing else may
  // wake the loop (no input comes), so wake it here.
  wxWakeUpIdle();
}

class SimulationApp : public wxApp {
 public:
  SimulationApp(SimulationSetup setup, GuiOptions options, int& exitCode)
      : setup_(std::move(setup)), options_(std::move(options)), exitCode_(exitCode) {}

  bool OnInit() override {
    // Not wxApp::OnInit(): it would parse the command line, which the program has done.
    if (options_.printDrag || !options_.screenshot.empty()) wxSetAssertHandler(printAssert);
    // Called from the event loop, not inside the signal handler, so it may close windows.
    SetSignalHandler(SIGTERM, closeTopWindow);
    SetSignalHandler(SIGINT, closeTopWindow);
    try {
      // Owned by wxWidgets: a top-level window deletes itself once closed.
      auto* frame =
          new SimulationFrame(std::move(setup_), options_, [this](int code) { exitCode_ = code; });
      frame->Show();
      SetTopWindow(frame);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s\n", error.what());
      exitCode_ = 1;
      return false;
    }
    return true;
  }

 private:
  SimulationSetup setup_;
  GuiOptions options_;
  int& exitCode_;
};

}  // namespace

int runSimulationApp(SimulationSetup setup, const GuiOptions& options, const char* programName) {
  int exitCode = 0;
  std::string name = programName != nullptr ? programName : "thyrix";
  char* arguments[] = {name.data(), nullptr};
  int count = 1;
  // wxEntry takes ownership of the application object and deletes it on return.
  wxApp::SetInstance(new SimulationApp(std::move(setup), options, exitCode));
  const int status = wxEntry(count, arguments);
  return status != 0 ? 1 : exitCode;
}

}  // namespace thyrix
