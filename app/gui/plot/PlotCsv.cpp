#include "gui/plot/PlotCsv.hpp"

#include "results/AtomicFile.hpp"
#include "results/NumberText.hpp"

#include <algorithm>
#include <map>
#include <ostream>
#include <vector>

namespace dropscope::gui::plot {

namespace {

struct NamedCurve {
    std::string name;
    const Curve* curve = nullptr;
};

std::vector<const Curve*> allCurves(const Figure& figure) {
    std::vector<const Curve*> curves;
    for (const SubPlot& subPlot : figure.subPlots) {
        for (const Curve& curve : subPlot.curves) curves.push_back(&curve);
    }
    return curves;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

// Every curve with the name its column or rows carry.
std::vector<NamedCurve> namedCurves(const Figure& figure) {
    std::map<std::string, int> uses;
    for (const Curve* curve : allCurves(figure)) ++uses[curve->name];
    std::vector<NamedCurve> curves;
    for (const SubPlot& subPlot : figure.subPlots) {
        for (const Curve& curve : subPlot.curves) {
            curves.push_back({uses[curve.name] > 1 ? subPlot.yLabel + ": " + curve.name : curve.name, &curve});
        }
    }
    return curves;
}

std::vector<double> samplesOf(const std::vector<double>& values, const Curve& curve) {
    return {values.begin(), values.begin() + static_cast<std::ptrdiff_t>(sampleCount(curve))};
}

void writeWide(const std::vector<NamedCurve>& curves, const std::string& xLabel, std::string& out) {
    out += csvField(xLabel);
    for (const NamedCurve& c : curves) out.append(",").append(csvField(c.name));
    out += '\n';
    const Curve& first = *curves.front().curve;
    for (std::size_t i = 0; i < sampleCount(first); ++i) {
        out += shortestText(first.x[i]);
        for (const NamedCurve& c : curves) out.append(",").append(shortestText(c.curve->y[i]));
        out += '\n';
    }
}

void writeLong(const std::vector<NamedCurve>& curves, std::string& out) {
    out += "curve,x,y\n";
    for (const NamedCurve& c : curves) {
        const std::string name = csvField(c.name);
        for (std::size_t i = 0; i < sampleCount(*c.curve); ++i) {
            out.append(name).append(",").append(shortestText(c.curve->x[i]));
            out.append(",").append(shortestText(c.curve->y[i])).append("\n");
        }
    }
}

}  // namespace

bool sharesX(const Figure& figure) {
    const std::vector<const Curve*> curves = allCurves(figure);
    return std::all_of(curves.begin(), curves.end(), [&](const Curve* curve) {
        return samplesOf(curve->x, *curve) == samplesOf(curves.front()->x, *curves.front());
    });
}

std::string plotCsv(const Figure& figure) {
    const std::vector<NamedCurve> curves = namedCurves(figure);
    std::string out;
    if (!curves.empty() && sharesX(figure)) {
        writeWide(curves, figure.xLabel, out);
    } else {
        writeLong(curves, out);
    }
    return out;
}

std::size_t plotCsvRows(const Figure& figure) {
    const std::vector<const Curve*> curves = allCurves(figure);
    if (curves.empty()) return 0;
    if (sharesX(figure)) return sampleCount(*curves.front());
    std::size_t rows = 0;
    for (const Curve* curve : curves) rows += sampleCount(*curve);
    return rows;
}

void writePlotCsv(const Figure& figure, const std::filesystem::path& file) {
    const std::string text = plotCsv(figure);
    writeFileAtomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace dropscope::gui::plot
