#include <GUIWx/Picking.h>
#include <GUIWx/WorldView.h>
#include <GUIWx/WxGUI.h>

#include <ThyrixLite/ColorDefinitions.h>

#include <wx/dcbuffer.h>
#include <wx/dcgraph.h>
#include <wx/dcmemory.h>
#include <wx/graphics.h>
#include <wx/image.h>
#include <wx/log.h>

#include <cmath>

namespace thyrix {
namespace {

constexpr int framesPerSecond = 60;
// A click this close to an object (pixels) still grabs it, so small ones are easy to take.
constexpr double pickTolerancePixels = 4;
// Zoom per wheel notch.
constexpr double zoomPerNotch = 1.2;

// Draws with anti-aliasing when the device allows it (a wxGCDC over @p dc), else on @p dc.
template <class Draw>
void antialiased(wxDC& dc, Draw draw) {
  wxGraphicsContext* context = wxGraphicsContext::CreateFromUnknownDC(dc);
  if (context == nullptr) {
    draw(dc);
    return;
  }
  context->SetAntialiasMode(wxANTIALIAS_DEFAULT);
  wxGCDC gcdc(context);  // takes ownership of the context
  draw(gcdc);
}

}  // namespace

WorldView::WorldView(wxWindow* parent, SimulationRunner& runner)
    : wxPanel(parent, wxID_ANY, wxDefaultPosition, wxDefaultSize,
              wxWANTS_CHARS | wxFULL_REPAINT_ON_RESIZE),
      runner_(&runner),
      timer_(this) {
  SetBackgroundStyle(wxBG_STYLE_PAINT);  // required by wxAutoBufferedPaintDC: no erase flicker
  SetMinSize(wxSize(200, 150));
  Bind(wxEVT_PAINT, &WorldView::onPaint, this);
  Bind(wxEVT_SIZE, &WorldView::onSize, this);
  Bind(wxEVT_TIMER, &WorldView::onTimer, this);
  Bind(wxEVT_LEFT_DOWN, &WorldView::onLeftDown, this);
  Bind(wxEVT_LEFT_UP, &WorldView::onLeftUp, this);
  Bind(wxEVT_RIGHT_DOWN, &WorldView::onPanDown, this);
  Bind(wxEVT_RIGHT_UP, &WorldView::onPanUp, this);
  Bind(wxEVT_MIDDLE_DOWN, &WorldView::onPanDown, this);
  Bind(wxEVT_MIDDLE_UP, &WorldView::onPanUp, this);
  Bind(wxEVT_MOTION, &WorldView::onMotion, this);
  Bind(wxEVT_MOUSEWHEEL, &WorldView::onWheel, this);
  Bind(wxEVT_KEY_DOWN, &WorldView::onKey, this);
  Bind(wxEVT_MOUSE_CAPTURE_LOST, &WorldView::onCaptureLost, this);
  const wxSize size = GetClientSize();
  transform_.setSize(size.x, size.y);
  timer_.Start(1000 / framesPerSecond);
}

WorldView::~WorldView() { detach(); }

void WorldView::detach() {
  timer_.Stop();
  if (runner_ != nullptr && dragging_) runner_->stopDrag();
  dragging_ = false;
  runner_ = nullptr;
}

Vector2 WorldView::worldAt(const wxPoint& pixel) const {
  return transform_.toWorld({static_cast<double>(pixel.x), static_cast<double>(pixel.y)});
}

void WorldView::onTimer(wxTimerEvent&) {
  if (runner_ == nullptr) return;
  std::shared_ptr<const WorldSnapshot> latest = runner_->latest();
  if (latest == snapshot_) return;
  snapshot_ = std::move(latest);
  const wxSize size = GetClientSize();
  if (!fitted_ && snapshot_->generation > 0 && size.x > 1 && size.y > 1) {
    transform_.setSize(size.x, size.y);
    transform_.fit(snapshot_->bounds);
    fitted_ = true;
  }
  Refresh(false);
  if (listener_) listener_(*snapshot_);
}

void WorldView::fitWorld() {
  keepFitted_ = true;
  if (snapshot_) {
    transform_.fit(snapshot_->bounds);
    fitted_ = true;
  }
  Refresh(false);
}

void WorldView::render(wxDC& dc) const {
  dc.SetBackground(*wxWHITE_BRUSH);
  dc.Clear();
  if (!snapshot_) return;
  antialiased(dc, [this](wxDC& target) {
    WxGUI gui(target, transform_);
    snapshot_->drawing.replay(gui);
    if (snapshot_->dragging) {
      // The rubber band of the mouse force: from the grabbed point to the cursor.
      gui.drawLine(snapshot_->dragPoint, snapshot_->dragTarget, colors::green);
      const real dot = static_cast<real>(3 / transform_.scale());
      gui.drawCircle(snapshot_->dragTarget, dot, 0, colors::green, colors::green);
    }
  });
  if (!snapshot_->error.empty()) {
    dc.SetTextForeground(*wxRED);
    dc.DrawText(wxString::FromUTF8(snapshot_->error), 8, 8);
  }
}

void WorldView::onPaint(wxPaintEvent&) {
  wxAutoBufferedPaintDC dc(this);
  render(dc);
}

bool WorldView::saveScreenshot(const wxString& path) const {
  const wxSize size = GetClientSize();
  if (size.x <= 0 || size.y <= 0) return false;
  wxBitmap bitmap(size.x, size.y, 24);
  {
    wxMemoryDC memory(bitmap);
    render(memory);
  }                       // the bitmap is deselected here, as SaveFile needs
  const wxLogNull quiet;  // report failure through the result, not a dialog
  return bitmap.ConvertToImage().SaveFile(path, wxBITMAP_TYPE_PNG);
}

void WorldView::onSize(wxSizeEvent& event) {
  const wxSize size = GetClientSize();
  transform_.setSize(size.x, size.y);
  if (keepFitted_ && snapshot_ && snapshot_->generation > 0 && size.x > 1 && size.y > 1) {
    transform_.fit(snapshot_->bounds);
    fitted_ = true;
  }
  Refresh(false);
  event.Skip();
}

void WorldView::onLeftDown(wxMouseEvent& event) {
  SetFocus();  // so that keys (F) reach the view
  if (runner_ == nullptr || !snapshot_ || dragging_) return;
  const Vector2 point = worldAt(event.GetPosition());
  const auto picked = pickObject(snapshot_->shapes, point,
                                 static_cast<real>(pickTolerancePixels / transform_.scale()));
  if (!picked) return;
  runner_->startDrag(snapshot_->generation, *picked, point);
  dragging_ = true;
  if (!HasCapture()) CaptureMouse();  // keep receiving the motion outside the view
}

void WorldView::onLeftUp(wxMouseEvent&) {
  endDrag();
  releaseMouseIfDone();
}

void WorldView::endDrag() {
  if (!dragging_) return;
  dragging_ = false;
  if (runner_ != nullptr) runner_->stopDrag();
}

void WorldView::releaseMouseIfDone() {
  if (!dragging_ && !panning_ && HasCapture()) ReleaseMouse();
}

void WorldView::onPanDown(wxMouseEvent& event) {
  SetFocus();
  panning_ = true;
  lastPan_ = event.GetPosition();
  if (!HasCapture()) CaptureMouse();
}

void WorldView::onPanUp(wxMouseEvent&) {
  panning_ = false;
  releaseMouseIfDone();
}

void WorldView::onMotion(wxMouseEvent& event) {
  const wxPoint position = event.GetPosition();
  if (dragging_ && runner_ != nullptr) runner_->dragTo(worldAt(position));
  if (panning_) {
    transform_.panBy(position.x - lastPan_.x, position.y - lastPan_.y);
    lastPan_ = position;
    keepFitted_ = false;
    Refresh(false);
  }
  if (!dragging_ && !panning_ && snapshot_) {
    // A hand over what can be grabbed.
    const bool over = pickObject(snapshot_->shapes, worldAt(position),
                                 static_cast<real>(pickTolerancePixels / transform_.scale()))
                          .has_value();
    SetCursor(over ? wxCursor(wxCURSOR_HAND) : wxNullCursor);
  }
}

void WorldView::onWheel(wxMouseEvent& event) {
  const int delta = event.GetWheelDelta() > 0 ? event.GetWheelDelta() : 120;
  const double notches = static_cast<double>(event.GetWheelRotation()) / delta;
  if (event.GetWheelAxis() != wxMOUSE_WHEEL_VERTICAL || notches == 0) return;
  const wxPoint p = event.GetPosition();
  transform_.zoomAbout({static_cast<double>(p.x), static_cast<double>(p.y)},
                       std::pow(zoomPerNotch, notches));
  keepFitted_ = false;
  if (dragging_ && runner_ != nullptr) runner_->dragTo(worldAt(p));  // the world moved under it
  Refresh(false);
}

void WorldView::onKey(wxKeyEvent& event) {
  if (event.GetKeyCode() == 'F' && !event.HasAnyModifiers()) {
    fitWorld();
    return;
  }
  event.Skip();
}

void WorldView::onCaptureLost(wxMouseCaptureLostEvent&) {
  endDrag();
  panning_ = false;
}

}  // namespace thyrix
