#include "app/bench_report.h"

// The four outputs of `sylva bench`. Numbers are formatted with <charconv>, so no output depends
// on the locale, and the same report always gives the same bytes. The SVG plot is written by hand:
// no Debian library draws a labelled scatter plot to SVG from C++, and the plot is small.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <tuple>

namespace sylva {

namespace {

using ordered_json = nlohmann::ordered_json;
using error_of = double (*)(const bench_configuration&);

double flip_error(const bench_configuration& c) {
    return c.error.perceptual;
}
double ssim_error(const bench_configuration& c) {
    return 1.0 - c.error.ssim;
}

// --- numbers and files -----------------------------------------------------------------------

// Six significant digits, never coarser than a whole number (byte and triangle counts stay exact).
double rounded(double v) {
    if (!std::isfinite(v)) return v;
    if (std::fabs(v) >= 1e6) return std::round(v);
    std::array<char, 32> text{};
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::general, 6).ptr;
    double r = v;
    std::from_chars(text.data(), end, r);
    return r;
}

// Shortest fixed notation that reads back as v: "2000000", "0.02", never an exponent.
std::string plain(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::array<char, 400> text{};  // fixed notation of 1e308 has 309 digits
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::fixed).ptr;
    return {text.data(), end};
}

std::string fixed(double v, int decimals) {
    if (!std::isfinite(v)) return plain(v);
    std::array<char, 400> text{};
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::fixed, decimals)
            .ptr;
    return {text.data(), end};
}

std::string significant(double v, int digits) {
    if (!std::isfinite(v)) return plain(v);
    std::array<char, 32> text{};
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::general, digits)
            .ptr;
    return {text.data(), end};
}

void write_atomically(const std::filesystem::path& path, const std::string& content) {
    const std::filesystem::path temporary = path.string() + ".tmp";
    std::error_code ignored;
    {
        std::ofstream out(temporary, std::ios::binary);
        out << content;
        out.close();
        if (!out) {
            std::filesystem::remove(temporary, ignored);
            throw std::runtime_error("cannot write " + path.string());
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
    }
}

std::vector<bool> front_flags(const bench_report& report, error_of error) {
    std::vector<double> ms;
    std::vector<double> err;
    for (const auto& c : report.configurations) {
        ms.push_back(c.frame_ms_median);
        err.push_back(error(c));
    }
    std::vector<bool> flags(report.configurations.size(), false);
    for (const std::size_t i : pareto_front(ms, err)) flags[i] = true;
    return flags;
}

const bench_configuration* find_configuration(const bench_report& report, std::string_view name) {
    for (const auto& c : report.configurations)
        if (c.name == name) return &c;
    return nullptr;
}

double entry_or_nan(const std::map<std::string, double>& values, const std::string& key) {
    const auto it = values.find(key);
    return it == values.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

// --- bench.json --------------------------------------------------------------------------------

// JSON has no infinity: +-inf become the strings "inf" and "-inf", NaN becomes null.
ordered_json number(double v) {
    if (std::isnan(v)) return nullptr;
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return rounded(v);
}

ordered_json numbers(const std::map<std::string, double>& values) {
    ordered_json j = ordered_json::object();
    for (const auto& [key, v] : values) j[key] = number(v);
    return j;
}

ordered_json configuration_json(const bench_configuration& c, bool on_front) {
    const bench_error& e = c.error;
    return {{"name", c.name},
            {"family", c.family},
            {"description", c.description},
            {"quality", number(c.quality)},
            {"frames", c.frames},
            {"frame_ms",
             {{"median", number(c.frame_ms_median)},
              {"min", number(c.frame_ms_min)},
              {"max", number(c.frame_ms_max)}}},
            {"cpu_ms", numbers(c.cpu_ms)},
            {"gpu_ms", numbers(c.gpu_ms)},
            {"primitives", numbers(c.primitives)},
            {"upload_bytes", number(c.upload_bytes)},
            {"peak_memory_mb", number(c.peak_memory_mb)},
            {"error",
             {{"psnr", number(e.psnr_db)},
              {"ssim", number(e.ssim)},
              {"perceptual", number(e.perceptual)},
              {"coverage_iou", number(e.coverage_iou)},
              {"popping", number(e.popping)},
              {"lighting_jump", number(e.lighting_jump)},
              {"rmse", number(e.rmse)},
              {"switches", e.switches}}},
            {"on_pareto_front", on_front}};
}

// --- bench.csv ---------------------------------------------------------------------------------

std::string csv_field(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string quoted = "\"";
    for (const char ch : text) {
        if (ch == '"') quoted += '"';
        quoted += ch;
    }
    return quoted + '"';
}

// Empty when not measured (NaN or absent), "inf" for an infinite PSNR.
std::string csv_number(double v) {
    return std::isnan(v) ? std::string() : plain(rounded(v));
}

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

struct panel {
    const char* title;
    const char* y_label;
    const char* id;
    error_of error;
    double left;
};

constexpr double k_plot_width = 490.0;
constexpr double k_plot_top = 86.0;
constexpr double k_plot_bottom = 426.0;

std::string axes_svg(const axis& x, const axis& y, const panel& p) {
    const double right = p.left + k_plot_width;
    std::string svg = "<g class=\"axes\" font-size=\"11\" fill=\"#333333\">\n";
    for (const double t : x.ticks)
        svg += "<line x1=\"" + px(x(t)) + "\" y1=\"" + px(k_plot_top) + "\" x2=\"" + px(x(t)) +
               "\" y2=\"" + px(k_plot_bottom) + "\" stroke=\"#e4e4e4\"/>\n<text x=\"" + px(x(t)) +
               "\" y=\"" + px(k_plot_bottom + 16) + "\" text-anchor=\"middle\">" +
               significant(t, 4) + "</text>\n";
    for (const double t : y.ticks)
        svg += "<line x1=\"" + px(p.left) + "\" y1=\"" + px(y(t)) + "\" x2=\"" + px(right) +
               "\" y2=\"" + px(y(t)) + "\" stroke=\"#e4e4e4\"/>\n<text x=\"" + px(p.left - 6) +
               "\" y=\"" + px(y(t) + 4) + "\" text-anchor=\"end\">" + significant(t, 4) +
               "</text>\n";
    svg += "<rect x=\"" + px(p.left) + "\" y=\"" + px(k_plot_top) + "\" width=\"" +
           px(k_plot_width) + "\" height=\"" + px(k_plot_bottom - k_plot_top) +
           "\" fill=\"none\" stroke=\"#333333\"/>\n";
    svg += "<text x=\"" + px(p.left + k_plot_width / 2) + "\" y=\"" + px(k_plot_bottom + 38) +
           "\" text-anchor=\"middle\" font-size=\"12\">median frame time (ms)" +
           (x.log ? ", log scale" : "") + "; bars: min to max</text>\n";
    const std::string mid = px((k_plot_top + k_plot_bottom) / 2);
    svg += "<text x=\"" + px(p.left - 50) + "\" y=\"" + mid +
           "\" text-anchor=\"middle\" font-size=\"12\" "
           "transform=\"rotate(-90 " +
           px(p.left - 50) + " " + mid + ")\">" + p.y_label + "</text>\n";
    svg += "<text x=\"" + px(p.left + k_plot_width / 2) + "\" y=\"" + px(k_plot_top - 10) +
           "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" + p.title +
           "</text>\n</g>\n";
    return svg;
}

std::string panel_svg(const bench_report& report, const panel& p,
                      const std::vector<double>& x_values,
                      const std::vector<std::pair<std::string, std::string>>& colours) {
    const axis x = frame_ms_axis(x_values, p.left, p.left + k_plot_width);
    auto drawable = [&](const bench_configuration& c) {
        return std::isfinite(p.error(c)) && std::isfinite(c.frame_ms_median) &&
               (!x.log || c.frame_ms_median > 0);
    };
    double highest = 0.0;
    for (const auto& c : report.configurations)
        if (drawable(c)) highest = std::max(highest, p.error(c));
    const axis y = error_axis(highest, k_plot_bottom, k_plot_top);
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
    svg += "<polyline class=\"pareto\" id=\"pareto-" + std::string(p.id) +
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
               significant(c.frame_ms_median, 4) + " ms, " + p.title + " " +
               significant(p.error(c), 4) + (on_front[pt.index] ? ", on the Pareto front" : "") +
               "</title>\n";
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
        placed_labels(points, report, {p.left, k_plot_top, p.left + k_plot_width, k_plot_bottom}) +
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

// --- summary.md --------------------------------------------------------------------------------

std::string ms_text(double ms) {
    return fixed(ms, ms < 10.0 ? 2 : ms < 100.0 ? 1 : 0);
}

std::string ratio_text(double ratio) {
    return fixed(ratio, ratio < 10.0 ? 2 : ratio < 100.0 ? 1 : 0) + "×";
}

std::string or_dash(double v, int decimals) {
    if (std::isnan(v)) return "—";
    if (std::isinf(v)) return v > 0 ? "∞" : "−∞";
    return fixed(v, decimals);
}

// Whole number with thousands separators: 2000000 -> "2,000,000".
std::string grouped(double v) {
    if (!std::isfinite(v)) return "—";
    const std::string digits = fixed(std::fabs(v), 0);
    std::string out = v < 0 ? "-" : "";
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string md_cell(std::string_view text) {
    std::string out;
    for (const char ch : text) {
        if (ch == '|') out += '\\';
        out += ch;
    }
    return out;
}

std::string table_md(const bench_report& report, const std::vector<bool>& on_front) {
    const bench_configuration* brute = find_configuration(report, "brute_force");
    std::vector<std::size_t> order(report.configurations.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return report.configurations[a].frame_ms_median < report.configurations[b].frame_ms_median;
    });
    std::string md =
        "| configuration | median ms [min–max] | speed-up vs brute_force | PSNR dB | SSIM | FLIP | "
        "coverage IoU | popping | lighting jump | triangles/frame | Pareto (FLIP) |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
    for (const std::size_t i : order) {
        const bench_configuration& c = report.configurations[i];
        const bench_error& e = c.error;
        const bool has_speed_up = brute && brute->frame_ms_median > 0 && c.frame_ms_median > 0;
        md += "| " + md_cell(c.name) + " | " + ms_text(c.frame_ms_median) + " [" +
              ms_text(c.frame_ms_min) + "–" + ms_text(c.frame_ms_max) + "] | " +
              (has_speed_up ? ratio_text(brute->frame_ms_median / c.frame_ms_median) : "—") +
              " | " + or_dash(e.psnr_db, 1) + " | " + or_dash(e.ssim, 4) + " | " +
              or_dash(e.perceptual, 4) + " | " + or_dash(e.coverage_iou, 4) + " | " +
              or_dash(e.popping, 2) + " | " + or_dash(e.lighting_jump, 2) + " | " +
              grouped(entry_or_nan(c.primitives, "triangles")) + " | " + (on_front[i] ? "★" : "") +
              " |\n";
    }
    return md;
}

bool is_candidate(const bench_configuration& c) {
    return c.name != "reference" && c.family != "reference";
}

std::string brute_force_sentence(const bench_report& report, const std::vector<bool>& on_front) {
    const bench_configuration* brute = find_configuration(report, "brute_force");
    if (!brute) return "";
    const bench_configuration* fastest = nullptr;  // with FLIP no worse than brute force's
    const bench_configuration* closest = nullptr;  // lowest FLIP otherwise
    for (std::size_t i = 0; i < report.configurations.size(); ++i) {
        const bench_configuration& c = report.configurations[i];
        if (!on_front[i] || !is_candidate(c) || &c == brute) continue;
        if (c.error.perceptual <= brute->error.perceptual &&
            (!fastest || c.frame_ms_median < fastest->frame_ms_median))
            fastest = &c;
        if (!closest || c.error.perceptual < closest->error.perceptual) closest = &c;
    }
    if (!fastest) {
        std::string sentence =
            "No configuration on the FLIP Pareto front has error no worse than brute_force's "
            "(FLIP " +
            or_dash(brute->error.perceptual, 4) + " at " + ms_text(brute->frame_ms_median) + " ms)";
        if (closest && closest->frame_ms_median > 0)
            sentence += "; the closest is " + closest->name + " at FLIP " +
                        or_dash(closest->error.perceptual, 4) + ", " +
                        ratio_text(brute->frame_ms_median / closest->frame_ms_median) + " faster";
        return sentence + ".";
    }
    return "The fastest configuration on the FLIP Pareto front with error no worse than "
           "brute_force's is " +
           fastest->name + ": FLIP " + or_dash(fastest->error.perceptual, 4) + " against " +
           or_dash(brute->error.perceptual, 4) + ", at " + ms_text(fastest->frame_ms_median) +
           " ms against " + ms_text(brute->frame_ms_median) + " ms (" +
           ratio_text(brute->frame_ms_median / fastest->frame_ms_median) + " faster).";
}

// "Similar" frame time: within 10% of the baseline's, or faster.
std::string baseline_sentence(const bench_report& report) {
    const bench_configuration* baseline = find_configuration(report, "baseline");
    if (!baseline) return "";
    const bench_configuration* best = nullptr;
    for (const auto& c : report.configurations) {
        if (&c == baseline || !is_candidate(c) ||
            !(c.frame_ms_median <= 1.1 * baseline->frame_ms_median) ||
            std::isnan(c.error.perceptual))
            continue;
        if (!best || c.error.perceptual < best->error.perceptual) best = &c;
    }
    const std::string at = "the baseline (FLIP " + or_dash(baseline->error.perceptual, 4) + " at " +
                           ms_text(baseline->frame_ms_median) + " ms)";
    if (!best)
        return "No other configuration runs within 10% of the frame time of " + at + " or faster.";
    if (!(best->error.perceptual < baseline->error.perceptual))
        return "No configuration within 10% of the frame time of " + at +
               " or faster has a lower FLIP error.";
    const std::string lower =
        best->error.perceptual > 0
            ? ratio_text(baseline->error.perceptual / best->error.perceptual) + " lower"
            : "zero";
    return "At similar or lower frame time, " + best->name + " reaches FLIP " +
           or_dash(best->error.perceptual, 4) + " at " + ms_text(best->frame_ms_median) +
           " ms against " + at + ": " + lower + " error, PSNR " + or_dash(best->error.psnr_db, 1) +
           " against " + or_dash(baseline->error.psnr_db, 1) + " dB, popping " +
           or_dash(best->error.popping, 2) + " against " + or_dash(baseline->error.popping, 2) +
           ".";
}

std::string reference_sentence(const bench_report& report) {
    const bench_configuration* reference = find_configuration(report, "reference");
    if (!reference) return "";
    const bench_error& e = reference->error;
    const bool identical = std::isinf(e.psnr_db) && e.psnr_db > 0 && e.ssim == 1.0 &&
                           e.perceptual == 0.0 && e.coverage_iou == 1.0;
    return std::string("The reference measured against itself gives PSNR ") +
           or_dash(e.psnr_db, 1) + " dB, SSIM " + or_dash(e.ssim, 4) + ", FLIP " +
           or_dash(e.perceptual, 4) + ", coverage IoU " + or_dash(e.coverage_iou, 4) +
           (identical ? ": identical images, as it must."
                      : ": NOT identical, so the error measurement is suspect.");
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<double>& frame_ms,
                                      const std::vector<double>& error) {
    if (frame_ms.size() != error.size())
        throw std::invalid_argument("pareto_front: " + std::to_string(frame_ms.size()) +
                                    " frame times but " + std::to_string(error.size()) + " errors");
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < frame_ms.size(); ++i)
        if (!std::isnan(frame_ms[i]) && !std::isnan(error[i])) order.push_back(i);
    // Faster first, then lower error, then lower index. Each later point is then either on the
    // front by a strictly lower error than every point before it, or dominated (or an equal point's
    // copy).
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return std::tie(frame_ms[a], error[a], a) < std::tie(frame_ms[b], error[b], b);
    });
    std::vector<std::size_t> front;
    for (const std::size_t i : order)
        if (front.empty() || error[i] < error[front.back()]) front.push_back(i);
    return front;
}

void write_bench_json(const std::filesystem::path& path, const bench_report& report) {
    const std::vector<bool> on_front = front_flags(report, flip_error);
    ordered_json configurations = ordered_json::array();
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        configurations.push_back(configuration_json(report.configurations[i], on_front[i]));
    const ordered_json root = {{"scenario", report.scenario},
                               {"source", report.source},
                               {"machine", report.machine},
                               {"gl_renderer", report.gl_renderer},
                               {"threads", report.threads},
                               {"width", report.width},
                               {"height", report.height},
                               {"frames", report.frames},
                               {"reference",
                                {{"samples_per_pixel", report.reference_samples_per_pixel},
                                 {"frame_ms_median", number(report.reference_frame_ms_median)}}},
                               {"configurations", configurations}};
    write_atomically(path, root.dump(2) + "\n");
}

void write_bench_csv(const std::filesystem::path& path, const bench_report& report) {
    const std::vector<bool> on_front = front_flags(report, flip_error);
    std::string csv =
        "name,family,quality,frames,frame_ms_median,frame_ms_min,frame_ms_max,cpu_ms_total,gpu_ms_"
        "total,"
        "triangles,points,lines,upload_bytes,peak_memory_mb,psnr_db,ssim,perceptual,coverage_iou,"
        "popping,"
        "lighting_jump,switches,on_pareto_front\n";
    for (std::size_t i = 0; i < report.configurations.size(); ++i) {
        const bench_configuration& c = report.configurations[i];
        const bench_error& e = c.error;
        const std::vector<std::string> fields = {
            csv_field(c.name),
            csv_field(c.family),
            csv_number(c.quality),
            std::to_string(c.frames),
            csv_number(c.frame_ms_median),
            csv_number(c.frame_ms_min),
            csv_number(c.frame_ms_max),
            csv_number(entry_or_nan(c.cpu_ms, "total")),
            csv_number(entry_or_nan(c.gpu_ms, "total")),
            csv_number(entry_or_nan(c.primitives, "triangles")),
            csv_number(entry_or_nan(c.primitives, "points")),
            csv_number(entry_or_nan(c.primitives, "lines")),
            csv_number(c.upload_bytes),
            csv_number(c.peak_memory_mb),
            csv_number(e.psnr_db),
            csv_number(e.ssim),
            csv_number(e.perceptual),
            csv_number(e.coverage_iou),
            csv_number(e.popping),
            csv_number(e.lighting_jump),
            std::to_string(e.switches),
            on_front[i] ? "true" : "false"};
        for (std::size_t f = 0; f < fields.size(); ++f) csv += (f ? "," : "") + fields[f];
        csv += "\n";
    }
    write_atomically(path, csv);
}

void write_bench_plot_svg(const std::filesystem::path& path, const bench_report& report) {
    constexpr double k_width = 1200.0;
    std::vector<double> x_values;
    for (const auto& c : report.configurations)
        for (const double v : {c.frame_ms_median, c.frame_ms_min, c.frame_ms_max})
            x_values.push_back(v);
    const auto colours = family_colours(report);
    const std::array<panel, 2> panels = {
        {{"FLIP", "perceptual error (FLIP)", "flip", flip_error, 80.0},
         {"1 − SSIM", "1 − SSIM", "ssim", ssim_error, 680.0}}};
    std::string body;
    for (const panel& p : panels) body += panel_svg(report, p, x_values, colours);
    double bottom = 0.0;
    body += legend_svg(colours, k_plot_bottom + 68.0, k_width, bottom);
    const std::string height = px(bottom + 8.0);
    const std::string title = "sylva bench: " + report.scenario;
    const std::string setup = report.machine + " · " + report.gl_renderer + " · " +
                              std::to_string(report.width) + "×" + std::to_string(report.height) +
                              " · " + std::to_string(report.frames) + " frames · " +
                              std::to_string(report.threads) + " threads · reference " +
                              std::to_string(report.reference_samples_per_pixel) + " spp";
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(k_width) +
                      "\" height=\"" + height + "\" viewBox=\"0 0 " + px(k_width) + " " + height +
                      "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n<title>" +
                      xml_escaped(title) +
                      "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    svg +=
        "<text x=\"600\" y=\"26\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">" +
        xml_escaped(title) +
        "</text>\n<text x=\"600\" y=\"46\" text-anchor=\"middle\" font-size=\"12\" "
        "fill=\"#444444\">" +
        xml_escaped(setup) + "</text>\n";
    write_atomically(path, svg + body + "</svg>\n");
}

void write_bench_summary_md(const std::filesystem::path& path, const bench_report& report) {
    const std::vector<bool> on_front = front_flags(report, flip_error);
    std::string md = "# sylva bench: " + report.scenario + "\n\n";
    md += std::to_string(report.frames) + " frames of `" + report.scenario + "` at " +
          std::to_string(report.width) + "×" + std::to_string(report.height) + " against a " +
          std::to_string(report.reference_samples_per_pixel) + " spp reference (" +
          ms_text(report.reference_frame_ms_median) + " ms/frame); " + report.machine + "; " +
          report.gl_renderer + "; " + std::to_string(report.threads) + " threads.\n\n";
    md += table_md(report, on_front) + "\n";
    md +=
        "Errors are means over the frames against the reference; ★ marks the Pareto front of "
        "median frame "
        "time against FLIP.\n\n";
    for (const std::string& sentence : {brute_force_sentence(report, on_front),
                                        baseline_sentence(report), reference_sentence(report)})
        if (!sentence.empty()) md += sentence + "\n\n";
    bool any_description = false;
    for (const auto& c : report.configurations)
        any_description = any_description || !c.description.empty();
    if (any_description) {
        md += "## Configurations\n\n";
        for (const auto& c : report.configurations)
            if (!c.description.empty()) md += "- `" + c.name + "`: " + c.description + "\n";
    }
    write_atomically(path, md);
}

}  // namespace sylva
