#pragma once

#include <boost/program_options.hpp>
#include <filesystem>
#include <string>

namespace sphcast {

// Command-line options of every tool, with Boost.Program_options. Long options take one dash
// (-case, -latestTime), as OpenFOAM users type them; two dashes work too.
class CommandLine {
 public:
  CommandLine(std::string application, std::string description);

  // -case DIR (default "."); every tool has it, and -help.
  // Further options go through options(): options()("latestTime", "...").
  boost::program_options::options_description_easy_init options();

  // Parses argv. Returns false when -help was given (the help is printed; exit 0). Throws an
  // Error for an unknown or malformed option, naming it and pointing to -help.
  bool parse(int argc, const char* const argv[]);

  std::filesystem::path casePath() const;
  bool has(const std::string& option) const { return values_.count(option) > 0; }
  template <class T>
  T get(const std::string& option) const {
    return values_[option].as<T>();
  }
  const std::string& application() const { return application_; }

 private:
  std::string application_;
  std::string description_;
  boost::program_options::options_description options_;
  boost::program_options::variables_map values_;
};

// Called by runApplication after a fatal error, with whether every rank stopped alike (a
// CollectiveError): a parallel run ends its other ranks (parallel/Communicator.h).
void setFatalErrorHandler(void (*handler)(bool everyRank));
// The rank named in a parallel run's error messages, "" in a serial run ("[1] " on rank 1).
void setErrorPrefix(const std::string& prefix);

// The common body of every main(): runs the tool, prints an Error as OpenFOAM prints a
// FatalError (in a parallel run each rank its own, a CollectiveError rank 0 only), and returns
// the exit status.
int runApplication(const std::string& application, int (*body)(int, const char* const[]),
                   int argc, const char* const argv[]);

}  // namespace sphcast
