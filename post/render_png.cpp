// Figure -> PNG through vtkContextView (off-screen render window on the X display).
#include "post/render_png.h"

#include "geometry/plan_shape.h"

#include <vtkBrush.h>
#include <vtkContext2D.h>
#include <vtkContextItem.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace isopound::post {
namespace {

// A context item that paints one Figure.
class FigureItem : public vtkContextItem {
 public:
  static FigureItem* New();
  vtkTypeMacro(FigureItem, vtkContextItem);
  const Figure* figure = nullptr;

  bool Paint(vtkContext2D* painter) override {
    const Figure& f = *figure;
    std::vector<float> xy;
    for (const FilledPolygon& poly : f.polygons) {
      if (poly.points.size() < 3) continue;
      painter->GetBrush()->SetColor(poly.colour.r, poly.colour.g, poly.colour.b, 255);
      painter->GetPen()->SetLineType(vtkPen::NO_PEN);
      // The context fills a polygon as a fan from its first vertex: a non-convex one (an L plan)
      // is filled piece by piece (its convex pieces, simple_polygon.h).
      std::vector<Vec2> outline;
      for (const Point2& p : poly.points) outline.push_back({p.x, p.y});
      std::vector<std::vector<Vec2>> pieces;
      bool left = false, right = false;  // turns both ways: not convex
      for (std::size_t i = 0, n = outline.size(); i < n; ++i) {
        const double turn =
            cross(outline[(i + 1) % n] - outline[i], outline[(i + 2) % n] - outline[(i + 1) % n]);
        left = left || turn > 0;
        right = right || turn < 0;
      }
      if (left && right) {
        try {
          const SimplePolygon split(outline);
          for (const ConvexPolygon& c : split.pieces())
            pieces.emplace_back(c.vertices().begin(), c.vertices().end());
        } catch (const InvalidPolygon&) {
          pieces.clear();
        }
      }
      if (pieces.empty()) pieces.push_back(outline);
      for (const std::vector<Vec2>& piece : pieces) {
        xy.clear();
        for (const Vec2& p : piece) {
          xy.push_back(static_cast<float>(p.x));
          xy.push_back(static_cast<float>(p.y));
        }
        painter->DrawPolygon(xy.data(), static_cast<int>(piece.size()));
      }
    }
    painter->GetPen()->SetLineType(vtkPen::SOLID_LINE);
    for (const Polyline& line : f.lines) {
      if (line.points.size() < 2) continue;
      xy.clear();
      for (const Point2& p : line.points) {
        xy.push_back(static_cast<float>(p.x));
        xy.push_back(static_cast<float>(p.y));
      }
      painter->GetPen()->SetColor(line.colour.r, line.colour.g, line.colour.b, 255);
      painter->GetPen()->SetWidth(static_cast<float>(line.width));
      painter->DrawPoly(xy.data(), static_cast<int>(line.points.size()));
    }
    for (const Marker& m : f.markers) {
      if (m.points.size() < 3) continue;
      xy.clear();
      for (const Point2& p : m.points) {
        xy.push_back(static_cast<float>(p.x));
        xy.push_back(static_cast<float>(p.y));
      }
      painter->GetBrush()->SetColor(m.fill.r, m.fill.g, m.fill.b, 255);
      painter->GetPen()->SetLineType(vtkPen::NO_PEN);
      painter->DrawPolygon(xy.data(), static_cast<int>(m.points.size()));
      if (m.edge_width <= 0.0) continue;
      xy.push_back(xy[0]);  // closed outline
      xy.push_back(xy[1]);
      painter->GetPen()->SetLineType(vtkPen::SOLID_LINE);
      painter->GetPen()->SetColor(m.edge.r, m.edge.g, m.edge.b, 255);
      painter->GetPen()->SetWidth(static_cast<float>(m.edge_width));
      painter->DrawPoly(xy.data(), static_cast<int>(m.points.size() + 1));
    }
    vtkTextProperty* tp = painter->GetTextProp();
    tp->SetFontFamily(VTK_FONT_FILE);
    for (const Text& t : f.texts) {
      tp->SetFontFile(t.bold ? kBoldFontFile : kFontFile);
      tp->SetFontSize(static_cast<int>(t.size));
      tp->SetColor(t.colour.r / 255.0, t.colour.g / 255.0, t.colour.b / 255.0);
      tp->SetJustification(t.h == HAlign::kLeft     ? VTK_TEXT_LEFT
                           : t.h == HAlign::kCentre ? VTK_TEXT_CENTERED
                                                    : VTK_TEXT_RIGHT);
      tp->SetVerticalJustification(t.v == VAlign::kBottom   ? VTK_TEXT_BOTTOM
                                   : t.v == VAlign::kCentre ? VTK_TEXT_CENTERED
                                                            : VTK_TEXT_TOP);
      tp->SetOrientation(t.angle_deg);
      painter->DrawString(static_cast<float>(t.at.x), static_cast<float>(t.at.y),
                          vtkStdString(t.text));
    }
    return true;
  }
};
vtkStandardNewMacro(FigureItem);

}  // namespace

void render_png(const Figure& figure, const std::string& path) {
  if (!std::filesystem::exists(kFontFile) || !std::filesystem::exists(kBoldFontFile))
    throw std::runtime_error(std::string("font not found: ") + kFontFile +
                             " (install fonts-dejavu-core)");
  vtkNew<vtkContextView> view;
  view->GetRenderer()->SetBackground(figure.background.r / 255.0, figure.background.g / 255.0,
                                     figure.background.b / 255.0);
  vtkRenderWindow* window = view->GetRenderWindow();
  window->SetOffScreenRendering(1);
  window->SetSize(figure.width, figure.height);
  window->SetMultiSamples(0);
  vtkNew<FigureItem> item;
  item->figure = &figure;
  view->GetScene()->AddItem(item);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(path))
    throw std::runtime_error("cannot write " + path);
}

}  // namespace isopound::post
