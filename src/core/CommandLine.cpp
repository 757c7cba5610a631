#include "core/CommandLine.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "core/OpenMPSettings.h"

namespace po = boost::program_options;

namespace sphcast {

namespace {

// The options as users type them, with one dash (Boost's own listing prints "--case"):
// "  -case DIR (=.)  the case folder".
void printOptions(std::ostream& out, const po::options_description& options) {
  std::vector<std::pair<std::string, std::string>> rows;
  std::size_t width = 0;
  for (const auto& option : options.options()) {
    std::string usage = "-" + option->long_name();
    const std::string parameter = option->format_parameter();
    if (!parameter.empty()) usage += " " + parameter;
    width = std::max(width, usage.size());
    rows.emplace_back(usage, option->description());
  }
  out << "Options:\n";
  for (const auto& [usage, description] : rows) {
    out << "  " << usage << std::string(width - usage.size() + 2, ' ') << description << '\n';
  }
}

}  // namespace

CommandLine::CommandLine(std::string application, std::string description)
    : application_(std::move(application)),
      description_(std::move(description)),
      options_("Options") {
  options_.add_options()("case", po::value<std::string>()->default_value(".")->value_name("DIR"),
                         "the case folder")("help", "print this help and exit");
}

po::options_description_easy_init CommandLine::options() { return options_.add_options(); }

bool CommandLine::parse(int argc, const char* const argv[]) {
  // allow_long_disguise: "-case" is the long option "case", as in OpenFOAM.
  const auto style = po::command_line_style::unix_style |
                     po::command_line_style::allow_long_disguise;
  try {
    po::store(po::command_line_parser(argc, argv).options(options_).style(style).run(), values_);
    po::notify(values_);
  } catch (const po::error& bad) {
    throw Error(application_ + ": " + bad.what() + " (see " + application_ + " -help)");
  }
  if (values_.count("help")) {
    std::cout << "Usage: " << application_ << " [OPTIONS]\n\n" << description_ << "\n\n";
    printOptions(std::cout, options_);
    std::cout << '\n';
    return false;
  }
  return true;
}

std::filesystem::path CommandLine::casePath() const { return values_["case"].as<std::string>(); }

namespace {
void (*fatalErrorHandler)(bool) = nullptr;
std::string errorPrefix;
}  // namespace

void setFatalErrorHandler(void (*handler)(bool everyRank)) { fatalErrorHandler = handler; }
void setErrorPrefix(const std::string& prefix) { errorPrefix = prefix; }

int runApplication(const std::string& application, int (*body)(int, const char* const[]),
                   int argc, const char* const argv[]) {
  adoptPassiveWaitPolicy(const_cast<char**>(argv));  // execv takes, and keeps, the same strings
  chooseThreadCount();
  // An exception cannot leave an OpenMP loop (a bad_alloc in one terminates the program): say
  // what it was before the program aborts.
  static std::string name;
  name = application;
  std::set_terminate([] {
    std::cout.flush();
    std::cerr << "\n--> sphCast FATAL ERROR in " << name << ": ";
    try {
      if (std::current_exception()) std::rethrow_exception(std::current_exception());
      std::cerr << "terminated without an exception";
    } catch (const std::bad_alloc&) {
      std::cerr << "out of memory (inside a parallel loop); a smaller case or more memory";
    } catch (const std::exception& error) {
      std::cerr << error.what() << " (inside a parallel loop)";
    } catch (...) {
      std::cerr << "unknown exception (inside a parallel loop)";
    }
    std::cerr << "\n\nExiting with status 134 (abort)" << std::endl;
    std::abort();
  });
  try {
    return body(argc, argv);
  } catch (const CollectiveError& error) {
    std::cout.flush();
    if (errorPrefix.empty()) {
      std::cerr << "\n--> sphCast FATAL ERROR in " << application << ":\n"
                << error.what() << "\n\nExiting with status 1\n";
    }
    if (fatalErrorHandler) fatalErrorHandler(true);
    return 1;
  } catch (const Error& error) {
    std::cout.flush();
    std::cerr << "\n"
              << errorPrefix << "--> sphCast FATAL ERROR in " << application << ":\n"
              << errorPrefix << error.what() << "\n\n"
              << errorPrefix << "Exiting with status 1\n";
    if (fatalErrorHandler) fatalErrorHandler(false);
    return 1;
  } catch (const std::exception& unexpected) {
    std::cout.flush();
    std::cerr << "\n"
              << errorPrefix << "--> sphCast FATAL ERROR in " << application
              << " (unexpected, please report): " << unexpected.what() << '\n';
    if (fatalErrorHandler) fatalErrorHandler(false);
    return 2;
  }
}

}  // namespace sphcast
