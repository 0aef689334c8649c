// IMPR_FONCTION: curves (functions, or explicit abscissas and ordinates) as
// columns of values (TABLEAU), as a Grace project file (XMGRACE), or plotted to
// an image (PNG, SVG; XMGRACE with PILOTE: EPS, POSTSCRIPT, PDF, PNG, SVG) by
// gnuplot, run as a process on a generated script and data files kept in the
// output folder.
// The command writes the script and the data; one gnuplot draws every plot of
// the run at its end (Session::plots), whatever ends it.
// PENTE='OUI' adds each curve's least-squares slope of log y against log x to its
// legend (convergence rates).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "commands/function_concepts.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "expr/tabulated.hpp"
#include "lang/operators.hpp"

extern char** environ;

namespace aster::lang {
namespace {

struct Curve {
  std::vector<double> x, y;
  std::string legend;
  int style = -1, colour = -1, marker = -1;
};

Curve curveOf(const Keywords& occ, Session& session) {
  Curve c;
  if (occ.has("FONCTION")) {
    const auto fc = occ.conceptPtr("FONCTION");
    const auto f = functionOf(fc);
    if (f->parameters().size() != 1)
      throw Error(occ.path + ": " + session.nameOf(*fc) + " takes " + std::to_string(f->parameters().size()) +
                  " parameters (" + expr::joinNames(f->parameters()) + "); a curve needs a function of one parameter");
    if (occ.has("LIST_PARA")) {
      c.x = std::static_pointer_cast<RealListConcept>(occ.conceptPtr("LIST_PARA"))->values;
      for (double x : c.x) c.y.push_back(f->evaluate(&x));
    } else if (auto t = std::dynamic_pointer_cast<const expr::Tabulated>(f)) {
      c.x = t->abscissas();
      c.y = t->ordinates();
    } else if (std::dynamic_pointer_cast<const expr::Constant>(f)) {
      throw Error(occ.path + ": " + session.nameOf(*fc) + " is a constant (DEFI_CONSTANTE): give LIST_PARA, the abscissas to draw it at");
    } else {
      throw Error(occ.path + ": " + session.nameOf(*fc) + " is a formula: give LIST_PARA, the abscissas to evaluate it at");
    }
    c.legend = occ.has("LEGENDE") ? occ.text("LEGENDE") : session.nameOf(*fc);
  } else {
    c.x = occ.reals("ABSCISSE");
    c.y = occ.reals("ORDONNEE");
    if (c.x.size() != c.y.size())
      throw Error(occ.path + ": ABSCISSE has " + std::to_string(c.x.size()) + " values, ORDONNEE " +
                  std::to_string(c.y.size()));
    if (occ.has("LEGENDE")) c.legend = occ.text("LEGENDE");
  }
  if (occ.has("STYLE")) c.style = static_cast<int>(occ.integer("STYLE"));
  if (occ.has("COULEUR")) c.colour = static_cast<int>(occ.integer("COULEUR"));
  if (occ.has("MARQUEUR")) c.marker = static_cast<int>(occ.integer("MARQUEUR"));
  return c;
}

// Least-squares slope of log y against log x over the points with x > 0, y > 0.
double logSlope(const Curve& c) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    if (!(c.x[i] > 0 && c.y[i] > 0)) continue;
    const double lx = std::log(c.x[i]), ly = std::log(c.y[i]);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
    ++n;
  }
  const double d = n * sxx - sx * sx;
  if (n < 2 || d == 0) throw Error("PENTE='OUI': curve '" + c.legend + "' has fewer than two points with x > 0 and y > 0");
  return (n * sxy - sx * sy) / d;
}

std::string number(double v) { return format::significant(v, 10); }

// A gnuplot string expression whose value is `s`, character for character.
// Texts and paths come from the study: in a double-quoted gnuplot string, `...`
// runs a shell command, so the text goes in single quotes (no substitution at
// all; '' is a quote), and the control characters a single-quoted string cannot
// hold (a newline ends the command) are octal escapes in double quotes,
// concatenated: ('line 1' . "\012" . 'line 2').
std::string gnuplotString(const std::string& s) {
  std::vector<std::string> pieces;
  std::string text;
  for (const char ch : s) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte >= 0x20 && byte != 0x7f) {
      text += ch == '\'' ? std::string("''") : std::string(1, ch);
      continue;
    }
    if (!text.empty()) pieces.push_back("'" + text + "'");
    text.clear();
    char escape[8];
    std::snprintf(escape, sizeof escape, "\"\\%03o\"", byte);
    pieces.push_back(escape);
  }
  if (!text.empty() || pieces.empty()) pieces.push_back("'" + text + "'");
  if (pieces.size() == 1) return pieces[0];
  std::string expression = "(" + pieces[0];
  for (std::size_t i = 1; i < pieces.size(); ++i) expression += " . " + pieces[i];
  return expression + ")";
}

std::string findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const auto p = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (access(p.c_str(), X_OK) == 0) return p.string();
  }
  return "";
}

// Runs gnuplot on the scripts, in order; true when it exits with status 0.
bool runGnuplot(const std::string& exe, const std::vector<std::filesystem::path>& scripts, bool showMessages) {
  std::vector<std::string> args{exe};
  for (const auto& s : scripts) args.push_back(std::filesystem::absolute(s).string());  // never taken for an option
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!showMessages) posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid;
  const int spawned = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return false;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// All plots in one gnuplot (each script starts with `reset session`); when that
// fails, each script alone, to say which ones gnuplot could not draw (and show
// gnuplot's messages once, for those).
std::vector<std::string> drawPlots(const std::vector<Session::PlotScript>& plots) {
  const std::string exe = findProgram("gnuplot");
  std::vector<std::string> failures;
  auto fail = [&](const Session::PlotScript& p, const std::string& why) {
    failures.push_back("<F> <" + p.where + ": " + why + " (script " + p.script.string() + ")");
  };
  std::vector<std::filesystem::path> scripts;
  for (const auto& p : plots) scripts.push_back(p.script);
  const bool together = !exe.empty() && runGnuplot(exe, scripts, false);
  for (const auto& p : plots) {
    if (exe.empty()) {
      fail(p, "gnuplot is no longer on the PATH");
      continue;
    }
    if (!together && !runGnuplot(exe, {p.script}, true)) {
      std::error_code ec;
      std::filesystem::remove(p.image, ec);  // what gnuplot left is no plot
      fail(p, "gnuplot failed (see its messages above)");
      continue;
    }
    std::error_code ec;
    if (std::filesystem::file_size(p.image, ec) == 0 || ec)
      fail(p, "gnuplot wrote no image " + p.image.string());
    else
      Messages::info("IMPR_FONCTION: plot written to " + p.image.string());
  }
  return failures;
}

// A text for a Grace project's double-quoted string: Grace reads its own escapes
// (\s2\N) in it, so they are kept; a quote or a control character is not text.
std::string graceString(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto byte = static_cast<unsigned char>(ch);
    out += ch == '"' ? '\'' : (byte < 0x20 || byte == 0x7f) ? ' ' : ch;
  }
  return out + "\"";
}

// XMGRACE without PILOTE: the curves as a Grace project (.agr), which xmgrace opens.
std::string graceProject(const Keywords& k, const std::vector<Curve>& curves) {
  std::ostringstream out;
  out << "# Grace project file\n@version 50125\n";
  if (k.has("TITRE")) out << "@title " << graceString(k.text("TITRE")) << "\n";
  if (k.has("SOUS_TITRE")) out << "@subtitle " << graceString(k.text("SOUS_TITRE")) << "\n";
  out << "@with g0\n";
  if (k.has("BORNE_X")) out << "@    world xmin " << number(k.reals("BORNE_X")[0]) << "\n@    world xmax " << number(k.reals("BORNE_X")[1]) << "\n";
  if (k.has("BORNE_Y")) out << "@    world ymin " << number(k.reals("BORNE_Y")[0]) << "\n@    world ymax " << number(k.reals("BORNE_Y")[1]) << "\n";
  out << "@    xaxes scale " << (k.text("ECHELLE_X") == "LOG" ? "Logarithmic" : "Normal") << "\n";
  out << "@    yaxes scale " << (k.text("ECHELLE_Y") == "LOG" ? "Logarithmic" : "Normal") << "\n";
  if (k.has("LEGENDE_X")) out << "@    xaxis label " << graceString(k.text("LEGENDE_X")) << "\n";
  if (k.has("LEGENDE_Y")) out << "@    yaxis label " << graceString(k.text("LEGENDE_Y")) << "\n";
  if (k.has("GRILLE_X")) out << "@    xaxis tick major " << number(k.real("GRILLE_X")) << "\n";
  if (k.has("GRILLE_Y")) out << "@    yaxis tick major " << number(k.real("GRILLE_Y")) << "\n";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const Curve& c = curves[i];
    out << "@    s" << i << " legend " << graceString(c.legend) << "\n";
    if (c.style >= 0) out << "@    s" << i << " line linestyle " << c.style << "\n";
    if (c.colour > 0) out << "@    s" << i << " line color " << c.colour << "\n";
    if (c.marker >= 0) out << "@    s" << i << " symbol " << c.marker << "\n";
  }
  for (std::size_t i = 0; i < curves.size(); ++i) {
    out << "@target G0.S" << i << "\n@type xy\n";
    for (std::size_t j = 0; j < curves[i].x.size(); ++j)
      out << number(curves[i].x[j]) << " " << number(curves[i].y[j]) << "\n";
    out << "&\n";
  }
  return out.str();
}

// gnuplot's terminal and the image's extension for FORMAT (PNG, SVG) or XMGRACE's PILOTE.
struct ImageKind {
  const char* terminal;
  const char* extension;
};

ImageKind imageKind(const std::string& name) {
  if (name == "PNG") return {"pngcairo size 900,650", ".png"};
  if (name == "SVG") return {"svg size 900,650", ".svg"};
  if (name == "EPS") return {"epscairo size 9in,6.5in", ".eps"};
  if (name == "POSTSCRIPT") return {"postscript landscape", ".ps"};
  if (name == "PDF") return {"pdfcairo size 9in,6.5in", ".pdf"};
  throw Error("no image format " + name);  // the catalogue's into lists only the above
}

ConceptPtr imprFonction(const Keywords& k, Session& session, ConceptPtr) {
  std::vector<Curve> curves;
  for (const auto& occ : k.factor("COURBE")) curves.push_back(curveOf(occ, session));
  const bool pente = k.text("PENTE") == "OUI";
  for (auto& c : curves) {
    if (!pente) continue;
    const double s = logSlope(c);
    char buf[48];
    std::snprintf(buf, sizeof buf, "pente %.3f", s);
    c.legend = c.legend.empty() ? std::string(buf) : c.legend + " (" + buf + ")";
    Messages::info("IMPR_FONCTION: " + c.legend);
  }
  const std::string format = k.text("FORMAT");
  const int unit = static_cast<int>(k.integer("UNITE"));
  const auto bound = session.units.find(unit);
  if (format == "TABLEAU") {
    std::ostringstream out;
    if (k.has("TITRE")) out << "# " << k.text("TITRE") << "\n";
    for (std::size_t i = 0; i < curves.size(); ++i) {
      out << "# COURBE " << i + 1 << (curves[i].legend.empty() ? "" : ": " + curves[i].legend) << "\n";
      out << "# " << (k.has("LEGENDE_X") ? k.text("LEGENDE_X") : "X") << "  "
          << (k.has("LEGENDE_Y") ? k.text("LEGENDE_Y") : "Y") << "\n";
      for (std::size_t j = 0; j < curves[i].x.size(); ++j)
        out << number(curves[i].x[j]) << "  " << number(curves[i].y[j]) << "\n";
      out << "\n";
    }
    const auto path = bound != session.units.end() ? bound->second
                                                   : session.outputFile("fort." + std::to_string(unit));
    session.checkUnitWritable(unit, path);
    // A file written for the first time in this run starts afresh, later writes add to it.
    appendAtomically(path, out.str(), session.files.written(path), &session.files);
    if (unit == 8 && bound == session.units.end()) {
      std::fputs(out.str().c_str(), stdout);
      std::fflush(stdout);
    }
    return nullptr;
  }
  if (format == "XMGRACE" && k.text("PILOTE").empty()) {
    const auto path = bound != session.units.end() ? bound->second
                                                   : session.outputFile("fort." + std::to_string(unit) + ".agr");
    session.checkUnitWritable(unit, path);
    const std::string project = graceProject(k, curves);
    session.writeFile(path, [&](const std::filesystem::path& tmp) { writeTextFile(tmp, project); });
    Messages::info("IMPR_FONCTION: Grace project " + path.string());
    return nullptr;
  }
  const ImageKind kind = imageKind(format == "XMGRACE" ? k.text("PILOTE") : format);
  const std::string ext = kind.extension;
  static int plots = 0;
  ++plots;
  std::filesystem::path image = bound != session.units.end()
                                    ? bound->second
                                    : session.outputFile("fonction_" + std::to_string(plots) + ext);
  session.checkUnitWritable(unit, image);
  if (session.files.written(image))  // a second plot to one unit gets a file of its own
    image = session.files.fresh(image.parent_path(), image.stem().string(), image.extension().string());
  session.files.addWritten(image);
  const auto dir = session.outputFile("");
  // Each plot's script and data files are its own (two images of one name in two folders).
  const std::string stem = session.files.fresh(dir, image.stem().string(), ".gp").stem().string();
  std::ostringstream gp;
  gp << "reset session\n";  // the scripts of a run are drawn by one gnuplot, one after the other
  gp << "set terminal " << kind.terminal << " noenhanced font 'Sans,11'\n";
  // Paths absolute: gnuplot takes a file name starting with '|' or '<' for a command.
  gp << "set output " << gnuplotString(std::filesystem::absolute(image).string()) << "\n";
  std::string title = k.has("TITRE") ? k.text("TITRE") : "";
  if (k.has("SOUS_TITRE")) title += (title.empty() ? "" : "\n") + k.text("SOUS_TITRE");
  if (!title.empty()) gp << "set title " << gnuplotString(title) << "\n";
  if (k.has("LEGENDE_X")) gp << "set xlabel " << gnuplotString(k.text("LEGENDE_X")) << "\n";
  if (k.has("LEGENDE_Y")) gp << "set ylabel " << gnuplotString(k.text("LEGENDE_Y")) << "\n";
  if (k.text("ECHELLE_X") == "LOG") gp << "set logscale x\n";
  if (k.text("ECHELLE_Y") == "LOG") gp << "set logscale y\n";
  if (k.has("BORNE_X")) gp << "set xrange [" << number(k.reals("BORNE_X")[0]) << ":" << number(k.reals("BORNE_X")[1]) << "]\n";
  if (k.has("BORNE_Y")) gp << "set yrange [" << number(k.reals("BORNE_Y")[0]) << ":" << number(k.reals("BORNE_Y")[1]) << "]\n";
  if (k.has("GRILLE_X")) gp << "set xtics " << number(k.real("GRILLE_X")) << "\n";
  if (k.has("GRILLE_Y")) gp << "set ytics " << number(k.real("GRILLE_Y")) << "\n";
  gp << "set grid\nset key top right box opaque\n";
  gp << "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const auto data = dir / (stem + "_" + std::to_string(i + 1) + ".dat");
    std::string values;
    for (std::size_t j = 0; j < curves[i].x.size(); ++j)
      values += number(curves[i].x[j]) + " " + number(curves[i].y[j]) + "\n";
    session.writeFile(data, [&](const std::filesystem::path& tmp) { writeTextFile(tmp, values); });
    const auto& c = curves[i];
    const bool line = c.style != 0, points = c.marker != 0;
    gp << (i ? ", \\\n     " : "") << gnuplotString(std::filesystem::absolute(data).string()) << " using 1:2 with "
       << (line && points ? "linespoints" : line ? "lines" : "points");
    if (c.colour > 0) gp << " linecolor " << c.colour;
    if (points && c.marker > 0) gp << " pointtype " << c.marker;
    if (line && c.style > 1) gp << " dashtype " << c.style;
    gp << " linewidth 2 title " << gnuplotString(c.legend.empty() ? "courbe " + std::to_string(i + 1) : c.legend);
  }
  gp << "\nunset output\n";  // closes the image before the next script opens its own
  const auto script = dir / (stem + ".gp");
  session.writeFile(script, [&](const std::filesystem::path& tmp) { writeTextFile(tmp, gp.str()); });
  if (findProgram("gnuplot").empty())
    throw Error("an image (FORMAT='PNG'/'SVG', XMGRACE with PILOTE) is drawn by gnuplot, which is not installed (Debian/Ubuntu: apt-get install gnuplot-nox); "
                "the script is " + script.string());
  std::error_code ec;
  std::filesystem::remove(image, ec);  // an image left by an earlier run must not pass for this one
  session.plots.push_back({script, image, "IMPR_FONCTION> " + session.where});
  session.drawPlots = drawPlots;
  Messages::info("IMPR_FONCTION: " + image.string() + " will be drawn by gnuplot at the end of the run");
  return nullptr;
}

RegisterOperator reg("IMPR_FONCTION", imprFonction);

}  // namespace
}  // namespace aster::lang
