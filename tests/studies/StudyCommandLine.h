#pragma once

// The command line of a study program, `program <study> [options]`: each study declares its own
// Boost.Program_options options (with their defaults), and --help lists every study with its
// options, each with a one-line meaning.

#include <boost/program_options.hpp>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace sphcast::studies {

namespace po = boost::program_options;

struct Study {
  std::string name;
  std::string meaning;  // one line, for --help
  std::function<void(po::options_description_easy_init)> declare;
  std::function<int(const po::variables_map&)> run;  // returns the exit status
};

// "150,165" (or "150 165"): the numbers; an error naming the option for anything else.
inline std::vector<double> numberList(const std::string& text, const std::string& option) {
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::istringstream in(spaced);
  std::vector<double> numbers;
  for (std::string word; in >> word;) {
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != word.size()) {
      throw po::error("--" + option + ": \"" + word + "\" is not a number");
    }
    numbers.push_back(value);
  }
  if (numbers.empty()) throw po::error("--" + option + ": no numbers in \"" + text + "\"");
  return numbers;
}

inline po::options_description optionsOf(const Study& study) {
  po::options_description options(study.name + " options", 100, 60);
  study.declare(options.add_options());
  return options;
}

inline void printHelp(std::ostream& out, const std::string& program, const std::string& about,
                      const std::vector<Study>& studies) {
  out << program << ": " << about << "\n\nusage: " << program
      << " <study> [options]   (a list of numbers: 150,165)\n\nstudies:\n";
  for (const Study& study : studies) {
    out << "  " << study.name << std::string(std::max<std::size_t>(2, 26 - study.name.size()), ' ')
        << study.meaning << "\n";
  }
  for (const Study& study : studies) out << "\n" << optionsOf(study);
}

// Parses `<study> [options]` and runs the study; --help (anywhere) prints the help. Returns the
// exit status: the study's, or 1 for a command line it cannot read (the error printed).
inline int runStudy(int argc, const char* const argv[], const std::string& about,
                    const std::vector<Study>& studies) {
  const std::string program =
      argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "study";
  const std::vector<std::string> arguments(argv + std::min(argc, 1), argv + argc);
  const bool help = std::find_if(arguments.begin(), arguments.end(), [](const std::string& a) {
                      return a == "--help" || a == "-h";
                    }) != arguments.end();
  if (help || arguments.empty()) {
    printHelp(help ? std::cout : std::cerr, program, about, studies);
    return help ? 0 : 1;
  }
  const auto study = std::find_if(studies.begin(), studies.end(),
                                  [&](const Study& s) { return s.name == arguments.front(); });
  try {
    if (study == studies.end()) throw po::error("no study \"" + arguments.front() + "\"");
    po::variables_map values;
    // argv + 1: the parser skips its first argument, here the study's name; no guessing, so
    // that a misspelt option is an error rather than another option's abbreviation
    const auto style =
        po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
    po::store(
        po::command_line_parser(argc - 1, argv + 1).options(optionsOf(*study)).style(style).run(),
        values);
    po::notify(values);
    return study->run(values);
  } catch (const po::error& error) {
    std::cerr << program << ": " << error.what() << " (" << program
              << " --help lists the studies and their options)" << std::endl;
    return 1;
  } catch (const std::exception& error) {  // a case that could not run
    std::cerr << program << " " << study->name << ": " << error.what() << std::endl;
    return 1;
  }
}

}  // namespace sphcast::studies
