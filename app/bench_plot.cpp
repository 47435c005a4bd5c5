// The plot of `sylva bench`: median frame time against error (FLIP, and 1 - SSIM), one panel
// each, with min-max bars, the Pareto front as a staircase, families coloured and brute force,
// baseline and reference marked by shape. Written by hand: no Debian library draws a labelled
// scatter plot to SVG from C++, and the plot is small. Deterministic for the same report.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <tuple>

#include "io/atomic_file.h"
#include "app/bench_format.h"
#include "app/bench_report.h"

namespace sylva {
namespace {

using namespace bench_format;

// --- the plot ----------------------------------------------------------------------------------

std::string xml_escaped(std::string_view text) {
    std::string out;
    for (const char ch : text) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

std::string px(double v) {
    return fixed(v, 1);
}

// Width of a label in pixels, estimated from its code points (no font metrics in an SVG writer).
double text_width(std::string_view text, double font_size) {
    const auto code_points = std::count_if(text.begin(), text.end(), [](char ch) {
        return (static_cast<unsigned char>(ch) & 0xC0u) != 0x80u;
    });
    return 0.58 * font_size * static_cast<double>(code_points);
}

// 1, 2 or 5 times a power of ten, at least x.
double nice_step(double x) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (const double m : {1.0, 2.0, 5.0})
        if (m * decade >= x * (1.0 - 1e-9)) return m * decade;
    return 10.0 * decade;
}

struct axis {
    bool log = false;
    double lo = 0.0;  // domain, in log10 units when `log`
    double hi = 1.0;
    double pixel_lo = 0.0;
    double pixel_hi = 1.0;
    std::vector<double> ticks;  // data units

    double operator()(double v) const {
        const double t = ((log ? std::log10(v) : v) - lo) / (hi - lo);
        return pixel_lo + t * (pixel_hi - pixel_lo);
    }
};

void linear_ticks(axis& a, double step) {
    for (auto k = static_cast<long long>(std::ceil(a.lo / step - 1e-9));
         static_cast<double>(k) * step <= a.hi + step * 1e-9; ++k)
        a.ticks.push_back(static_cast<double>(k) * step);
}

// Frame times: log scale when they span more than 4x (ticks 1-2-5 per decade, or denser when
// the range is short), linear otherwise.
axis frame_ms_axis(const std::vector<double>& values, double pixel_lo, double pixel_hi) {
    axis a;
    a.pixel_lo = pixel_lo;
    a.pixel_hi = pixel_hi;
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const double v : values) {
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (lo > hi) return a;  // nothing measured: [0, 1]
    if (lo > 0.0 && hi / lo > 4.0) {
        a.log = true;
        const double pad = 0.05 * (std::log10(hi) - std::log10(lo));
        a.lo = std::log10(lo) - pad;
        a.hi = std::log10(hi) + pad;
        for (const auto& mantissas : {std::vector<double>{1}, std::vector<double>{1, 2, 5},
                                      std::vector<double>{1, 2, 3, 5, 7}}) {
            a.ticks.clear();
            for (double e = std::floor(a.lo); e <= std::ceil(a.hi); e += 1.0)
                for (const double m : mantissas) {
                    const double tick = m * std::pow(10.0, e);
                    if (std::log10(tick) >= a.lo && std::log10(tick) <= a.hi)
                        a.ticks.push_back(tick);
                }
            if (a.ticks.size() >= 4) break;
        }
        return a;
    }
    const double span = hi > lo ? hi - lo : std::max(std::fabs(lo) * 0.2, 1e-3);
    const double step = nice_step(span / 5.0);
    a.lo = std::floor((lo - 0.05 * span) / step) * step;
    if (lo >= 0.0) a.lo = std::max(a.lo, 0.0);
    a.hi = std::ceil((hi + 0.05 * span) / step) * step;
    linear_ticks(a, step);
    return a;
}

// Errors: linear from 0.
axis error_axis(double highest, double pixel_lo, double pixel_hi) {
    axis a;
    a.pixel_lo = pixel_lo;
    a.pixel_hi = pixel_hi;
    const double step = nice_step(highest > 0.0 ? highest * 1.05 / 5.0 : 0.02);
    a.hi = std::ceil(std::max(highest, 1e-12) * 1.05 / step) * step;
    linear_ticks(a, step);
    return a;
}

enum class marker_shape { circle, square, diamond, triangle };

marker_shape shape_of(const bench_configuration& c) {
    if (c.family == "brute_force" || c.name == "brute_force") return marker_shape::square;
    if (c.family == "baseline" || c.name == "baseline") return marker_shape::diamond;
    if (c.family == "reference" || c.name == "reference") return marker_shape::triangle;
    return marker_shape::circle;
}

std::string marker(marker_shape shape, double x, double y, const std::string& colour, bool filled) {
    const std::string paint = " fill=\"" + (filled ? colour : std::string("#ffffff")) +
                              "\" stroke=\"" + colour + "\" stroke-width=\"1.8\"/>";
    switch (shape) {
        case marker_shape::square:
            return "<rect x=\"" + px(x - 5) + "\" y=\"" + px(y - 5) +
                   "\" width=\"10\" height=\"10\"" + paint;
        case marker_shape::diamond:
            return "<path d=\"M" + px(x) + "," + px(y - 7) + " L" + px(x + 7) + "," + px(y) + " L" +
                   px(x) + "," + px(y + 7) + " L" + px(x - 7) + "," + px(y) + " Z\"" + paint;
        case marker_shape::triangle:
            return "<path d=\"M" + px(x) + "," + px(y - 7) + " L" + px(x + 6.5) + "," + px(y + 5) +
                   " L" + px(x - 6.5) + "," + px(y + 5) + " Z\"" + paint;
        case marker_shape::circle:
            break;
    }
    return "<circle cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"5\"" + paint;
}

// Families in order of first appearance; brute force, baseline and reference keep fixed colours
// so they read the same in every plot.
std::vector<std::pair<std::string, std::string>> family_colours(const bench_report& report) {
    constexpr std::array<const char*, 8> k_palette = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd",
                                                      "#8c564b", "#e377c2", "#17becf", "#bcbd22"};
    std::vector<std::pair<std::string, std::string>> colours;
    std::size_t next = 0;
    for (const auto& c : report.configurations) {
        if (std::any_of(colours.begin(), colours.end(),
                        [&](const auto& f) { return f.first == c.family; }))
            continue;
        std::string colour;
        if (c.family == "brute_force")
            colour = "#000000";
        else if (c.family == "baseline")
            colour = "#d62728";
        else if (c.family == "reference")
            colour = "#7f7f7f";
        else
            colour = k_palette[next++ % k_palette.size()];
        colours.emplace_back(c.family, colour);
    }
    return colours;
}

const std::string& colour_of(const std::vector<std::pair<std::string, std::string>>& colours,
                             const std::string& family) {
    return std::find_if(colours.begin(), colours.end(),
                        [&](const auto& f) { return f.first == family; })
        ->second;
}

struct box {
    double x0, y0, x1, y1;
    bool overlaps(const box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

struct plotted {
    std::size_t index;
    double x, y;
};

constexpr double k_label_size = 11.0;

// Labels go, left to right, to the first of six places around the marker that overlaps the fewest
// labels and markers already there and stays inside the plot.
std::string placed_labels(const std::vector<plotted>& points, const bench_report& report,
                          const box& plot) {
    struct place {
        double dx, dy;
        const char* anchor;
    };
    constexpr std::array<place, 6> k_places = {{{8, -6, "start"},
                                                {8, 14, "start"},
                                                {-8, -6, "end"},
                                                {-8, 14, "end"},
                                                {0, -11, "middle"},
                                                {0, 21, "middle"}}};
    std::vector<box> taken;
    for (const auto& p : points) taken.push_back({p.x - 6, p.y - 6, p.x + 6, p.y + 6});
    std::vector<plotted> order = points;
    std::stable_sort(order.begin(), order.end(),
                     [](const plotted& a, const plotted& b) { return a.x < b.x; });
    std::string svg;
    for (const auto& p : order) {
        const std::string& name = report.configurations[p.index].name;
        const double w = text_width(name, k_label_size);
        int best_score = std::numeric_limits<int>::max();
        box best_box{};
        const place* best = nullptr;
        for (const place& candidate : k_places) {
            const double left = candidate.anchor[0] == 's'   ? 0.0
                                : candidate.anchor[0] == 'e' ? -w
                                                             : -w / 2;
            const box b{p.x + candidate.dx + left, p.y + candidate.dy - 9,
                        p.x + candidate.dx + left + w, p.y + candidate.dy + 3};
            int score =
                (b.x0 < plot.x0 || b.x1 > plot.x1 || b.y0 < plot.y0 || b.y1 > plot.y1) ? 4 : 0;
            for (const box& t : taken) score += b.overlaps(t) ? 1 : 0;
            if (score < best_score) {
                best_score = score;
                best_box = b;
                best = &candidate;
            }
        }
        taken.push_back(best_box);
        svg += "<text x=\"" + px(p.x + best->dx) + "\" y=\"" + px(p.y + best->dy) +
               "\" text-anchor=\"" + best->anchor + "\">" + xml_escaped(name) + "</text>\n";
    }
    return svg;
}

// One panel: one error of one lighting family's configurations (errors against different
// references share no axis or front).
struct panel {
    std::string title;
    const char* y_label;
    std::string id;
    error_of error;
    double left;
    double top;
    std::string lighting;

    double bottom() const;
};

constexpr double k_plot_width = 490.0;
constexpr double k_plot_height = 340.0;
constexpr double k_first_plot_top = 86.0;
constexpr double k_row_height = k_plot_height + 110.0;  // axis labels and the next row's title

double panel::bottom() const { return top + k_plot_height; }

std::string axes_svg(const axis& x, const axis& y, const panel& p) {
    const double right = p.left + k_plot_width;
    const double plot_top = p.top;
    const double plot_bottom = p.bottom();
    std::string svg = "<g class=\"axes\" font-size=\"11\" fill=\"#333333\">\n";
    for (const double t : x.ticks)
        svg += "<line x1=\"" + px(x(t)) + "\" y1=\"" + px(plot_top) + "\" x2=\"" + px(x(t)) +
               "\" y2=\"" + px(plot_bottom) + "\" stroke=\"#e4e4e4\"/>\n<text x=\"" + px(x(t)) +
               "\" y=\"" + px(plot_bottom + 16) + "\" text-anchor=\"middle\">" +
               significant(t, 6) + "</text>\n";
    for (const double t : y.ticks)
        svg += "<line x1=\"" + px(p.left) + "\" y1=\"" + px(y(t)) + "\" x2=\"" + px(right) +
               "\" y2=\"" + px(y(t)) + "\" stroke=\"#e4e4e4\"/>\n<text x=\"" + px(p.left - 6) +
               "\" y=\"" + px(y(t) + 4) + "\" text-anchor=\"end\">" + significant(t, 4) +
               "</text>\n";
    svg += "<rect x=\"" + px(p.left) + "\" y=\"" + px(plot_top) + "\" width=\"" +
           px(k_plot_width) + "\" height=\"" + px(plot_bottom - plot_top) +
           "\" fill=\"none\" stroke=\"#333333\"/>\n";
    svg += "<text x=\"" + px(p.left + k_plot_width / 2) + "\" y=\"" + px(plot_bottom + 38) +
           "\" text-anchor=\"middle\" font-size=\"12\">median frame time (ms)" +
           (x.log ? ", log scale" : "") + "; bars: min to max</text>\n";
    const std::string mid = px((plot_top + plot_bottom) / 2);
    svg += "<text x=\"" + px(p.left - 50) + "\" y=\"" + mid +
           "\" text-anchor=\"middle\" font-size=\"12\" "
           "transform=\"rotate(-90 " +
           px(p.left - 50) + " " + mid + ")\">" + p.y_label + "</text>\n";
    svg += "<text x=\"" + px(p.left + k_plot_width / 2) + "\" y=\"" + px(plot_top - 10) +
           "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" + p.title +
           "</text>\n</g>\n";
    return svg;
}

std::string panel_svg(const bench_report& report, const panel& p,
                      const std::vector<double>& x_values,
                      const std::vector<std::pair<std::string, std::string>>& colours) {
    const axis x = frame_ms_axis(x_values, p.left, p.left + k_plot_width);
    const double plot_top = p.top;
    const double plot_bottom = p.bottom();
    auto drawable = [&](const bench_configuration& c) {
        return c.lighting == p.lighting && std::isfinite(p.error(c)) && std::isfinite(c.frame_ms_median) &&
               (!x.log || c.frame_ms_median > 0);
    };
    double highest = 0.0;
    for (const auto& c : report.configurations)
        if (drawable(c)) highest = std::max(highest, p.error(c));
    const axis y = error_axis(highest, plot_bottom, plot_top);
    const std::vector<bool> on_front = front_flags(report, p.error);

    std::string svg = axes_svg(x, y, p);
    std::vector<plotted> points;
    std::vector<plotted> front;
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        if (drawable(report.configurations[i]))
            points.push_back({i, x(report.configurations[i].frame_ms_median),
                              y(p.error(report.configurations[i]))});
    for (const auto& pt : points)
        if (on_front[pt.index]) front.push_back(pt);
    std::sort(front.begin(), front.end(),
              [](const plotted& a, const plotted& b) { return a.x < b.x; });
    // The front as a staircase: what it dominates lies above and to the right.
    svg += "<polyline class=\"pareto\" id=\"pareto-" + p.id +
           "\" fill=\"none\" stroke=\"#444444\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\" "
           "points=\"";
    for (std::size_t k = 0; k < front.size(); ++k) {
        if (k > 0) svg += px(front[k].x) + "," + px(front[k - 1].y) + " ";
        svg += px(front[k].x) + "," + px(front[k].y) + (k + 1 < front.size() ? " " : "");
    }
    svg += "\"/>\n";
    for (const auto& pt : points) {
        const bench_configuration& c = report.configurations[pt.index];
        const std::string& colour = colour_of(colours, c.family);
        svg += "<g class=\"configuration\">\n<title>" + xml_escaped(c.name) + ": " +
               significant(c.frame_ms_median, 4) + " ms, " + xml_escaped(p.title) + " " +
               significant(p.error(c), 4) + ", lighting jump " +
               (std::isfinite(c.error.lighting_jump) ? significant(c.error.lighting_jump, 3) : std::string("n/a")) +
               " over " + std::to_string(c.error.transitions) + " transitions" +
               (on_front[pt.index] ? ", on the Pareto front" : "") + "</title>\n";
        if (std::isfinite(c.frame_ms_min) && std::isfinite(c.frame_ms_max) &&
            (!x.log || c.frame_ms_min > 0)) {
            const double x0 = x(c.frame_ms_min);
            const double x1 = x(c.frame_ms_max);
            svg += "<path d=\"M" + px(x0) + "," + px(pt.y) + " H" + px(x1) + " M" + px(x0) + "," +
                   px(pt.y - 3) + " V" + px(pt.y + 3) + " M" + px(x1) + "," + px(pt.y - 3) + " V" +
                   px(pt.y + 3) + "\" stroke=\"" + colour +
                   "\" stroke-width=\"1\" fill=\"none\" opacity=\"0.7\"/>\n";
        }
        svg += marker(shape_of(c), pt.x, pt.y, colour, on_front[pt.index]) + "\n</g>\n";
    }
    svg +=
        "<g class=\"labels\" font-size=\"11\" fill=\"#222222\">\n" +
        placed_labels(points, report, {p.left, plot_top, p.left + k_plot_width, plot_bottom}) +
        "</g>\n";
    return svg;
}

// Families by colour, then what the marks mean; rows wrap at the plot's width.
std::string legend_svg(const std::vector<std::pair<std::string, std::string>>& colours, double top,
                       double width, double& bottom) {
    struct entry {
        std::string text;
        std::string mark;
    };
    std::vector<entry> entries;
    for (const auto& [family, colour] : colours) {
        bench_configuration c;
        c.family = family;
        entries.push_back({family, marker(shape_of(c), 0, 0, colour, true)});
    }
    entries.push_back({"on the Pareto front", marker(marker_shape::circle, 0, 0, "#444444", true)});
    entries.push_back({"dominated", marker(marker_shape::circle, 0, 0, "#444444", false)});
    entries.push_back({"Pareto front",
                       "<path d=\"M-10,0 H10\" stroke=\"#444444\" stroke-width=\"1.5\" "
                       "stroke-dasharray=\"5 3\"/>"});
    std::string svg = "<g class=\"legend\" font-size=\"12\" fill=\"#222222\">\n";
    double x = 80.0;
    double y = top;
    for (const entry& e : entries) {
        const double advance = 18.0 + text_width(e.text, 12.0) + 20.0;
        if (x + advance > width - 20.0 && x > 80.0) {
            x = 80.0;
            y += 20.0;
        }
        svg += "<g transform=\"translate(" + px(x) + " " + px(y) + ")\">" + e.mark +
               "<text x=\"14\" y=\"4\">" + xml_escaped(e.text) + "</text></g>\n";
        x += advance;
    }
    bottom = y + 16.0;
    return svg + "</g>\n";
}

}  // namespace

void write_bench_plot_svg(const std::filesystem::path& path, const bench_report& report) {
    constexpr double k_width = 1200.0;
    std::vector<double> x_values;
    for (const auto& c : report.configurations)
        for (const double v : {c.frame_ms_median, c.frame_ms_min, c.frame_ms_max}) x_values.push_back(v);
    const auto colours = family_colours(report);
    std::string body;
    double top = k_first_plot_top;
    for (const bench_lighting_family& family : report.lighting_families) {
        const std::string suffix = report.lighting_families.size() > 1 ? " (" + family.name + " lighting)" : "";
        const std::array<panel, 2> panels = {
            {{"FLIP" + suffix, "perceptual error (FLIP)", "flip-" + family.name, flip_error, 80.0, top, family.name},
             {"1 − SSIM" + suffix, "1 − SSIM", "ssim-" + family.name, ssim_error, 680.0, top, family.name}}};
        for (const panel& p : panels) body += panel_svg(report, p, x_values, colours);
        top += k_row_height;
    }
    double bottom = 0.0;
    body += legend_svg(colours, top - k_row_height + k_plot_height + 68.0, k_width, bottom);
    const std::string height = px(bottom + 8.0);
    const std::string title = "sylva bench: " + report.scenario;
    const std::string setup = report.machine + " · " + report.gl_renderer + " · " + std::to_string(report.width) +
                              "×" + std::to_string(report.height) + " · " + std::to_string(report.frames) +
                              " frames · " + std::to_string(report.threads) + " threads · each against the " +
                              std::to_string(report.reference_samples_per_pixel) + " spp reference lit as it is";
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(k_width) + "\" height=\"" + height +
                      "\" viewBox=\"0 0 " + px(k_width) + " " + height +
                      "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n<title>" + xml_escaped(title) +
                      "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    svg += "<text x=\"600\" y=\"26\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">" +
           xml_escaped(title) + "</text>\n<text x=\"600\" y=\"46\" text-anchor=\"middle\" font-size=\"12\" fill=\"#444444\">" +
           xml_escaped(setup) + "</text>\n";
    write_atomically(path, svg + body + "</svg>\n");
}

}  // namespace sylva
