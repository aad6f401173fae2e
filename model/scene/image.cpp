// SPDX-License-Identifier: Apache-2.0
// Images from spans, PNG output and heatmaps with a drawn colour bar (image.hpp).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "image.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace specular {

Image::Image(int w, int h)
    : width(w), height(h), value(static_cast<size_t>(w) * h, 0.0), covered(static_cast<size_t>(w) * h, 0) {}

Image render(const Raster& raster, const Evaluator& evaluator) {
  Image img(raster.width, raster.height);
  std::vector<double> buf;
  for (const Span& s : raster.spans) {
    buf.assign(static_cast<size_t>(s.pixels()), 0.0);
    evaluator(s, std::span<double>(buf));
    for (int i = 0; i < s.pixels(); ++i) {
      img.at(s.x_start + i, s.y) += buf[i];
      img.covered[static_cast<size_t>(s.y) * img.width + s.x_start + i] = 1;
    }
  }
  return img;
}

Evaluator phong_evaluator(const Scene& scene) {
  return [&scene](const Span& s, std::span<double> out) {
    for (size_t i = 0; i < out.size(); ++i) out[i] = pixel_truth(scene, s, static_cast<int>(i));
  };
}

Evaluator float_model_evaluator() {
  return [](const Span& s, std::span<double> out) {
    const ScanlineSetup st = scanline_setup(s.setup_in);
    for (size_t i = 0; i < out.size(); ++i) out[i] = pixel_blinn(st, s.setup_in.n, static_cast<int>(i));
  };
}

Evaluator golden_evaluator(const device::DeviceModel& dm) {
  return [&dm](const Span& s, std::span<double> out) {
    const std::vector<uint32_t> line = dm.line(host::span_registers(s.setup_in, dm.format()));
    for (size_t i = 0; i < out.size() && i < line.size(); ++i) out[i] = device::c_value(line[i], dm.format());
  };
}

Image difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("difference: image sizes differ");
  Image d(a.width, a.height);
  for (size_t k = 0; k < d.value.size(); ++k) {
    d.covered[k] = a.covered[k] | b.covered[k];
    d.value[k] = a.value[k] - b.value[k];
  }
  return d;
}

ImageErrorStats error_stats(const Image& err) {
  ImageErrorStats st;
  double sum2 = 0;
  for (int y = 0; y < err.height; ++y) {
    for (int x = 0; x < err.width; ++x) {
      if (!err.is_covered(x, y)) continue;
      const double e = err.at(x, y);
      ++st.pixels;
      sum2 += e * e;
      if (std::abs(e) > st.max_abs || st.argmax_x < 0) {
        st.max_abs = std::max(st.max_abs, std::abs(e));
        st.argmax_x = x;
        st.argmax_y = y;
      }
    }
  }
  st.rms = st.pixels ? std::sqrt(sum2 / st.pixels) : 0.0;
  return st;
}

// ---------------------------------------------------------------- bitmap font

namespace {

struct Glyph {
  char c;
  std::array<const char*, 7> rows;
};

// 5x7 glyphs drawn for this project ('#' = ink).
constexpr Glyph kFont[] = {
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
    {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
    {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
    {'/', {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."}},
    {'|', {"..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {'%', {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"}},
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
    {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
    {'D', {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
    {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
    {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
    {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
    {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
    {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
};

const Glyph* find_glyph(char c) {
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kFont)
    if (g.c == u) return &g;
  return nullptr;
}

constexpr int kGlyphW = 5, kGlyphH = 7, kAdvance = 6;

}  // namespace

bool font_has_glyph(char c) { return c == ' ' || find_glyph(c) != nullptr; }

int text_width(const std::string& text, int scale) {
  return text.empty() ? 0 : (static_cast<int>(text.size()) * kAdvance - 1) * scale;
}

void draw_text(std::vector<uint8_t>& rgb, int w, int h, int x, int y, const std::string& text, int scale,
               const std::array<uint8_t, 3>& colour) {
  for (size_t k = 0; k < text.size(); ++k) {
    const Glyph* g = find_glyph(text[k]);
    if (!g) continue;  // spaces and unknown characters leave a gap
    const int gx = x + static_cast<int>(k) * kAdvance * scale;
    for (int r = 0; r < kGlyphH; ++r) {
      for (int c = 0; c < kGlyphW; ++c) {
        if (g->rows[r][c] != '#') continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            const int px = gx + c * scale + dx, py = y + r * scale + dy;
            if (px < 0 || py < 0 || px >= w || py >= h) continue;
            uint8_t* p = &rgb[(static_cast<size_t>(py) * w + px) * 3];
            p[0] = colour[0];
            p[1] = colour[1];
            p[2] = colour[2];
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------- PNG output

namespace {

constexpr std::array<uint8_t, 3> kBackground{28, 30, 38};

uint8_t to_byte(double v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// Diverging map on u in [-1, 1]: blue -> white -> red.
std::array<uint8_t, 3> diverging(double u) {
  u = std::clamp(u, -1.0, 1.0);
  const double a = std::abs(u);
  // Interpolate from white to a saturated end colour; sqrt stretches small errors.
  const double s = std::sqrt(a);
  const std::array<double, 3> end = u < 0 ? std::array<double, 3>{0.13, 0.27, 0.85} : std::array<double, 3>{0.85, 0.10, 0.10};
  return {to_byte(1.0 + (end[0] - 1.0) * s), to_byte(1.0 + (end[1] - 1.0) * s), to_byte(1.0 + (end[2] - 1.0) * s)};
}

std::string sci(double v, bool plus) {
  char buf[32];
  std::snprintf(buf, sizeof buf, plus ? "%+.2E" : "%.2E", v);
  return buf;
}

}  // namespace

void write_png(const std::string& path, const Image& img, double scale) {
  std::vector<uint8_t> rgb(static_cast<size_t>(img.width) * img.height * 3);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      uint8_t* p = &rgb[(static_cast<size_t>(y) * img.width + x) * 3];
      if (!img.is_covered(x, y)) {
        std::copy(kBackground.begin(), kBackground.end(), p);
        continue;
      }
      p[0] = p[1] = p[2] = to_byte(img.at(x, y) * scale);
    }
  }
  write_rgb_png(path, img.width, img.height, rgb);
}

void write_rgb_png(const std::string& path, int w, int h, const std::vector<uint8_t>& rgb) {
  if (!stbi_write_png(path.c_str(), w, h, 3, rgb.data(), w * 3))
    throw std::runtime_error(path + ": cannot write the PNG file");
}

namespace {
// The legend's metrics at image width w: text size, padding, text and bar heights.
struct LegendMetrics {
  int scale, pad, text_h, bar_h;
  explicit LegendMetrics(int w) : scale(w >= 400 ? 2 : 1), pad(4 * scale), text_h(7 * scale), bar_h(10 * scale) {}
  int height() const { return pad + text_h + pad + bar_h + pad / 2 + text_h + pad; }
};
}  // namespace

int legend_height(int w) { return LegendMetrics(w).height(); }

void draw_legend(std::vector<uint8_t>& rgb, int w, int top, const std::array<uint8_t, 3>& background,
                 const std::string& title, const std::string& short_title,
                 const std::function<std::array<uint8_t, 3>(double)>& bar, const std::string& lo,
                 const std::string& hi) {
  const LegendMetrics m(w);
  const int h = top + m.height();
  for (int y = top; y < h; ++y)
    for (int x = 0; x < w; ++x) std::copy(background.begin(), background.end(), &rgb[(static_cast<size_t>(y) * w + x) * 3]);
  const std::array<uint8_t, 3> ink{235, 235, 235};
  int y = top + m.pad;
  draw_text(rgb, w, h, m.pad, y, text_width(title, m.scale) > w - 2 * m.pad ? short_title : title, m.scale, ink);
  y += m.text_h + m.pad;
  const int x0 = m.pad, x1 = w - m.pad;  // the bar spans [x0, x1)
  for (int x = x0; x < x1; ++x) {
    const double u = x1 - x0 > 1 ? -1.0 + 2.0 * (x - x0) / (x1 - x0 - 1) : 0.0;
    const auto c = bar(u);
    for (int dy = 0; dy < m.bar_h; ++dy) std::copy(c.begin(), c.end(), &rgb[(static_cast<size_t>(y + dy) * w + x) * 3]);
  }
  y += m.bar_h + m.pad / 2;
  draw_text(rgb, w, h, x0, y, lo, m.scale, ink);
  draw_text(rgb, w, h, (x0 + x1 - text_width("0", m.scale)) / 2, y, "0", m.scale, ink);
  draw_text(rgb, w, h, x1 - text_width(hi, m.scale), y, hi, m.scale, ink);
}

void write_heatmap_png(const std::string& path, const Image& err, const std::string& label, double range) {
  const ImageErrorStats st = error_stats(err);
  double R = range > 0 ? range : st.max_abs;
  const bool all_zero = !(R > 0);
  if (all_zero) R = 1.0;  // any colour scale works; the labels say 0

  const int W = err.width;
  const int H = err.height + legend_height(W);
  std::vector<uint8_t> rgb(static_cast<size_t>(W) * H * 3, 0);
  for (int y = 0; y < err.height; ++y) {
    for (int x = 0; x < W; ++x) {
      uint8_t* p = &rgb[(static_cast<size_t>(y) * W + x) * 3];
      const auto c = err.is_covered(x, y) ? diverging(err.at(x, y) / R) : kBackground;
      std::copy(c.begin(), c.end(), p);
    }
  }
  // Strip: label, colour bar, numeric range.
  draw_legend(rgb, W, err.height, kBackground, label + "  MAX|E| " + sci(st.max_abs, false), label, diverging,
              all_zero ? "0" : sci(-R, true), all_zero ? "0" : sci(R, true));
  write_rgb_png(path, W, H, rgb);
}

}  // namespace specular
