// SPDX-License-Identifier: Apache-2.0
// Checks that every relative link in every Markdown file of the repository resolves: the
// target file or directory exists, and a #fragment names a heading of the target Markdown
// file (GitHub's anchor rules: lower case, punctuation dropped, spaces to '-', "-1", "-2"
// for repeats). Links with a scheme (https:, mailto:) are not checked; links inside code
// spans and fenced code blocks are not links.
//
//   check_md_links ROOT          every .md that git tracks or would track (else every .md
//                                outside build*/ and .git/); exit 1 and one line per
//                                broken link, 0 when all resolve
//   check_md_links --self-test   the checker on a generated tree with known good and
//                                broken links; exit 0 only if it finds exactly the broken ones
//
// Source files (C++, SystemVerilog, Python, shell, CMake, Makefile) are checked too: every
// path to a Markdown file they mention (`docs/device.md#fixed-point-contract`, taken from the
// repository root or from the file's own folder) must exist with that heading, and a citation
// of a document a clone does not have (the domain specification's section numbers, or an
// issue tracker's "issue N item M") is an error.
#include <algorithm>
#include <cctype>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<std::string> read_lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

// Lines outside fenced code blocks, with inline code spans blanked.
std::vector<std::string> prose_lines(const fs::path& p, bool keep_code = false) {
  std::vector<std::string> out;
  bool fenced = false;
  for (std::string line : read_lines(p)) {
    const auto first = line.find_first_not_of(' ');
    if (first != std::string::npos && (line.compare(first, 3, "```") == 0 || line.compare(first, 3, "~~~") == 0)) {
      fenced = !fenced;
      out.emplace_back();
      continue;
    }
    if (fenced) {
      out.emplace_back();
      continue;
    }
    // Blank `code` spans (a run of backticks closes with the same run).
    std::string clean;
    for (size_t i = 0; i < line.size();) {
      if (line[i] == '`') {
        size_t run = 0;
        while (i + run < line.size() && line[i + run] == '`') ++run;
        const std::string ticks(run, '`');
        const size_t close = line.find(ticks, i + run);
        if (close == std::string::npos) {
          clean += line.substr(i);
          break;
        }
        // Headings keep the code text (GitHub's anchors do); elsewhere it is blanked so that
        // link syntax inside code is not checked.
        clean += keep_code ? line.substr(i + run, close - i - run) : std::string(close + run - i, ' ');
        i = close + run;
      } else {
        clean += line[i++];
      }
    }
    out.push_back(clean);
  }
  return out;
}

std::string slug(const std::string& heading) {
  std::string s;
  for (unsigned char c : heading) {
    if (std::isalnum(c) || c == '-' || c == '_') s += static_cast<char>(std::tolower(c));
    else if (c == ' ') s += '-';
    else if (c >= 0x80) s += static_cast<char>(c);  // non-ASCII letters are kept
  }
  return s;
}

std::set<std::string> anchors(const fs::path& md) {
  std::set<std::string> out;
  std::map<std::string, int> seen;
  static const std::regex heading(R"(^ {0,3}#{1,6}[ \t]+(.*?)[ \t#]*$)");
  for (const std::string& line : prose_lines(md, true)) {
    std::smatch m;
    if (!std::regex_match(line, m, heading)) continue;
    // Link text of links inside a heading counts, the target does not.
    const std::string text = std::regex_replace(m[1].str(), std::regex(R"(\[([^\]]*)\]\([^)]*\))"), "$1");
    const std::string base = slug(text);
    const int n = seen[base]++;
    out.insert(n == 0 ? base : base + "-" + std::to_string(n));
  }
  return out;
}

// One message per broken link in `md`.
std::vector<std::string> check_file(const fs::path& md, const fs::path& root) {
  std::vector<std::string> bad;
  static const std::regex link(R"(!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))");
  static const std::regex scheme(R"(^[A-Za-z][A-Za-z0-9+.-]*:)");
  const auto lines = prose_lines(md);
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    for (std::sregex_iterator it(lines[ln].begin(), lines[ln].end(), link), end; it != end; ++it) {
      const std::string target = (*it)[1].str();
      if (std::regex_search(target, scheme)) continue;
      const auto hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const std::string frag = hash == std::string::npos ? "" : target.substr(hash + 1);
      const fs::path resolved = path.empty() ? md : (path[0] == '/' ? root / path.substr(1) : md.parent_path() / path);
      const std::string where = fs::relative(md, root).string() + ":" + std::to_string(ln + 1) + ": ";
      if (!fs::exists(resolved)) {
        bad.push_back(where + "'" + target + "': no such file " + fs::relative(resolved.lexically_normal(), root).string());
        continue;
      }
      if (!frag.empty() && resolved.extension() == ".md" && !anchors(resolved).count(frag))
        bad.push_back(where + "'" + target + "': no heading with anchor #" + frag);
    }
  }
  return bad;
}

// One message per broken reference in the source file `src`.
std::vector<std::string> check_source(const fs::path& src, const fs::path& root) {
  std::vector<std::string> bad;
  static const std::regex md_ref(R"(((?:\.\./|[A-Za-z0-9_-]+/)*[A-Za-z0-9_.-]+\.md)(#[A-Za-z0-9_-]+)?)");
  // Assembled from pieces so that this file does not cite what it forbids.
  static const std::string spec = std::string("SP") + "EC";
  // Any "issue N" / "issues N": the tracker is not in the clone (an upstream bug is cited by
  // its URL or as "#N").
  static const std::regex outside(spec + " section|" + spec + " §|\\b[Ii]ss" + "ues? [0-9]+");
  const auto lines = read_lines(src);
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    const std::string where = fs::relative(src, root).string() + ":" + std::to_string(ln + 1) + ": ";
    std::smatch m;
    if (std::regex_search(lines[ln], m, outside))
      bad.push_back(where + "'" + m[0].str() + "': cites a document outside the repository; cite docs/ instead");
    for (std::sregex_iterator it(lines[ln].begin(), lines[ln].end(), md_ref), end; it != end; ++it) {
      const std::string path = (*it)[1].str(), frag = (*it)[2].matched ? (*it)[2].str().substr(1) : "";
      // A reference is a path whose first folder exists (docs/x.md, ../README.md); bare names
      // and placeholders (report.md, OUT/summary.md) are files a tool writes, not references.
      const auto slash = path.find('/');
      if (slash == std::string::npos) continue;
      const std::string first = path.substr(0, slash);
      if (first != ".." && !fs::is_directory(root / first) && !fs::is_directory(src.parent_path() / first)) continue;
      fs::path resolved = root / path;
      if (!fs::exists(resolved)) resolved = src.parent_path() / path;
      if (!fs::exists(resolved)) {
        bad.push_back(where + "'" + (*it)[0].str() + "': no such file");
        continue;
      }
      if (!frag.empty() && !anchors(resolved).count(frag))
        bad.push_back(where + "'" + (*it)[0].str() + "': no heading with anchor #" + frag);
    }
  }
  return bad;
}

// Tracked (or untracked, not ignored) files matching the git pathspecs, or nothing outside git.
std::vector<fs::path> git_files(const fs::path& root, const std::string& pathspecs) {
  std::vector<fs::path> out;
  const std::string cmd = "git -C '" + root.string() + "' ls-files --cached --others --exclude-standard -- " + pathspecs;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    std::string all;
    while (size_t n = fread(buf, 1, sizeof buf, p)) all.append(buf, n);
    if (pclose(p) == 0) {
      std::istringstream in(all);
      std::string line;
      while (std::getline(in, line))
        if (!line.empty() && fs::exists(root / line)) out.push_back(root / line);
    }
  }
  return out;
}

// The files of the tree: in a git checkout those git_files lists, elsewhere every file whose
// name matches `name` outside .git and build* folders.
std::vector<fs::path> tree_files(const fs::path& root, const std::string& pathspecs, const std::regex& name) {
  if (fs::exists(root / ".git")) return git_files(root, pathspecs);
  std::vector<fs::path> out;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const std::string n = it->path().filename().string();
    if (it->is_directory() && (n == ".git" || n.rfind("build", 0) == 0)) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && std::regex_match(n, name)) out.push_back(it->path());
  }
  return out;
}

std::vector<fs::path> source_files(const fs::path& root) {
  static const std::regex name(R"(.*\.(cpp|hpp|inl|sv|svh|py|sh|cmake|f)$|CMakeLists\.txt|Makefile)");
  return tree_files(root, "'*.cpp' '*.hpp' '*.inl' '*.sv' '*.svh' '*.py' '*.sh' '*.cmake' '*CMakeLists.txt' 'Makefile' '*.f'",
                    name);
}

std::vector<fs::path> markdown_files(const fs::path& root) {
  static const std::regex name(R"(.*\.md)");
  return tree_files(root, "'*.md'", name);
}

int check_tree(const fs::path& root, std::vector<std::string>* found) {
  auto files = markdown_files(root);
  std::sort(files.begin(), files.end());
  int count = 0;
  for (const auto& f : files) {
    for (const auto& b : check_file(f, root)) {
      if (found) found->push_back(b);
      else std::cout << b << "\n";
      ++count;
    }
  }
  auto sources = source_files(root);
  std::sort(sources.begin(), sources.end());
  for (const auto& f : sources) {
    // This checker's own source names broken references on purpose (its self-test).
    if (f.filename() == "check_md_links.cpp") continue;
    for (const auto& b : check_source(f, root)) {
      if (found) found->push_back(b);
      else std::cout << b << "\n";
      ++count;
    }
  }
  if (!found)
    std::cout << files.size() << " Markdown files, " << sources.size() << " source files, " << count
              << " broken links or references\n";
  return count;
}

int self_test() {
  const fs::path root = fs::temp_directory_path() / ("md_links_selftest_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "docs");
  std::ofstream(root / "code.txt") << "x\n";
  std::ofstream(root / "README.md") << "# Top\n\n[ok](docs/a.md) [ok anchor](docs/a.md#second-part-x) [ok dir](docs)\n"
                                       "[ok file](code.txt) [web](https://example.com/none) `[code](nofile.md)`\n"
                                       "[BROKEN1](docs/missing.md)\n```\n[fenced](nofile2.md)\n```\n";
  std::ofstream(root / "docs" / "a.md") << "# A\n## Second part: x\n## Repeat\n## Repeat\n## Code (`make x`)\n"
                                           "[ok up](../README.md#top) [ok self](#repeat-1) [BROKEN2](#repeat-2)\n"
                                           "[ok code heading](#code-make-x)\n"
                                           "[BROKEN3](../README.md#nowhere) [BROKEN4](../code.txt.bak)\n";
  std::ofstream(root / "docs" / "tool.cpp") << "// see docs/a.md#second-part-x and ../README.md#top (ok), writes OUT/x.md\n"
                                               "// BROKEN5 docs/gone.md, BROKEN6 docs/a.md#nope\n"
                                               "// BROKEN7: as SP" "EC sec" "tion 4 says\n"
                                               "// BROKEN8: (see iss" "ue 12, items 3 and 4); fine: verilator#123\n";
  std::vector<std::string> found;
  check_tree(root, &found);
  fs::remove_all(root);
  int bad = 0;
  const std::vector<std::string> expected{"docs/missing.md", "#repeat-2",   "../README.md#nowhere", "../code.txt.bak",
                                         "docs/gone.md",    "docs/a.md#nope", "SP" "EC sec" "tion", "iss" "ue 12"};
  if (found.size() != expected.size()) ++bad;
  for (const auto& e : expected)
    if (std::none_of(found.begin(), found.end(), [&](const std::string& f) { return f.find("'" + e + "'") != std::string::npos; }))
      ++bad;
  for (const auto& f : found) std::cout << "found: " << f << "\n";
  std::cout << (bad ? "self-test FAILED\n" : "self-test passed: exactly the 8 broken links and references found\n");
  return bad ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: check_md_links ROOT | --self-test\n";
    return 2;
  }
  if (std::string(argv[1]) == "--self-test") return self_test();
  // No README found means the file listing failed (git error, wrong ROOT): nothing was checked.
  if (markdown_files(fs::path(argv[1])).empty()) {
    std::cerr << "check_md_links: " << argv[1] << ": no Markdown files found (not the repository root, or git failed)\n";
    return 1;
  }
  return check_tree(fs::path(argv[1]), nullptr) ? 1 : 0;
}
