#include <GUIWx/ActivationPanel.h>

#include <wx/dcbuffer.h>
#include <wx/settings.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace thyrix {

ActivationPanel::ActivationPanel(wxWindow* parent, int width)
    : wxPanel(parent, wxID_ANY, wxDefaultPosition, wxSize(width, -1)) {
  SetBackgroundStyle(wxBG_STYLE_PAINT);  // everything is painted in onPaint: no flicker
  SetMinSize(wxSize(width, 100));
  Bind(wxEVT_PAINT, &ActivationPanel::onPaint, this);
  Bind(wxEVT_SIZE, [this](wxSizeEvent& event) {
    Refresh(false);
    event.Skip();
  });
}

void ActivationPanel::setValues(std::span<const real> sensors, std::span<const real> effectors) {
  const bool same =
      std::equal(sensors.begin(), sensors.end(), sensors_.begin(), sensors_.end()) &&
      std::equal(effectors.begin(), effectors.end(), effectors_.begin(), effectors_.end());
  if (same) return;  // nothing to repaint
  sensors_.assign(sensors.begin(), sensors.end());
  effectors_.assign(effectors.begin(), effectors.end());
  Refresh(false);
}

void ActivationPanel::onPaint(wxPaintEvent&) {
  wxAutoBufferedPaintDC dc(this);
  dc.SetBackground(wxBrush(wxSystemSettings::GetColour(wxSYS_COLOUR_WINDOW)));
  dc.Clear();
  const wxSize size = GetClientSize();
  const wxColour text = wxSystemSettings::GetColour(wxSYS_COLOUR_WINDOWTEXT);
  dc.SetTextForeground(text);
  wxFont small = GetFont();
  small.SetPointSize(std::max(6, small.GetPointSize() - 2));
  dc.SetFont(small);
  const int lineHeight = dc.GetCharHeight();
  const int margin = 6;

  // Rows share the height left after the two headers, between 2 and 16 pixels each.
  const std::size_t rows = sensors_.size() + effectors_.size();
  const int headers = 2 * (lineHeight + margin);
  const int available = std::max(0, size.y - headers - margin);
  const int rowHeight = rows == 0 ? 16 : std::clamp(available / static_cast<int>(rows), 2, 16);
  const bool numbered = rowHeight >= lineHeight - 2;
  const int labelWidth = numbered ? dc.GetTextExtent("00").x + 4 : 0;
  const int barLeft = margin + labelWidth;
  const int barWidth = std::max(10, size.x - barLeft - margin);

  int y = margin;
  const auto group = [&](const char* title, const std::vector<real>& values,
                         const wxColour& colour) {
    dc.DrawText(wxString::Format("%s (%zu)", title, values.size()), margin, y);
    y += lineHeight + 2;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double v = std::clamp(static_cast<double>(values[i]), 0.0, 1.0);
      const int h = std::max(1, rowHeight - 1);
      if (numbered) dc.DrawText(wxString::Format("%zu", i), margin, y + (h - lineHeight) / 2);
      dc.SetPen(*wxTRANSPARENT_PEN);
      dc.SetBrush(wxBrush(wxColour(225, 225, 225)));
      dc.DrawRectangle(barLeft, y, barWidth, h);
      dc.SetBrush(wxBrush(colour));
      dc.DrawRectangle(barLeft, y, static_cast<int>(std::lround(v * barWidth)), h);
      y += rowHeight;
    }
    y += margin;
  };
  group("Sensors", sensors_, wxColour(50, 110, 210));
  group("Effectors", effectors_, wxColour(235, 130, 20));
}

}  // namespace thyrix
