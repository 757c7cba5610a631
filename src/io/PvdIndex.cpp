#include "io/PvdIndex.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <charconv>
#include <map>
#include <system_error>
#include <tuple>

#include "core/AtomicFile.h"
#include "core/Error.h"

namespace sphcast {

namespace {

namespace fs = std::filesystem;

std::string xmlEscaped(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&apos;";
        break;
      default:
        escaped += c;
    }
  }
  return escaped;
}

bool sortsBefore(const PvdEntry& a, const PvdEntry& b) {
  return std::tie(a.time, a.part) < std::tie(b.time, b.part);
}

// Sorted by (time, part); of equal (time, part) the last given wins (a time written again).
std::vector<PvdEntry> sortedUnique(std::vector<PvdEntry> entries) {
  std::reverse(entries.begin(), entries.end());
  std::stable_sort(entries.begin(), entries.end(), sortsBefore);
  const auto sameSlot = [](const PvdEntry& a, const PvdEntry& b) {
    return a.time == b.time && a.part == b.part;
  };
  entries.erase(std::unique(entries.begin(), entries.end(), sameSlot), entries.end());
  return entries;
}

// Index of each cloud name among all the distinct names, in name order.
std::map<std::string, int> partIndices(const std::vector<PvdEntry>& entries) {
  std::map<std::string, int> indices;
  for (const PvdEntry& entry : entries) indices.emplace(entry.part, 0);
  int index = 0;
  for (auto& [part, partIndex] : indices) partIndex = index++;
  return indices;
}

std::string collectionXml(const std::vector<PvdEntry>& entries) {
  const std::map<std::string, int> indices = partIndices(entries);
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <Collection>\n";
  for (const PvdEntry& entry : entries) {
    xml += "    <DataSet timestep=\"" + xmlEscaped(entry.timeName) + "\" group=\"\" part=\"" +
           std::to_string(indices.at(entry.part)) + "\" name=\"" + xmlEscaped(entry.part) +
           "\" file=\"" + xmlEscaped(entry.file) + "\"/>\n";
  }
  xml += "  </Collection>\n</VTKFile>\n";
  return xml;
}

// ---- reading ------------------------------------------------------------------------------

// Appends VTK's error and warning texts to the std::string given as client data, so that VTK
// prints nothing.
void collectMessage(vtkObject*, unsigned long, void* clientData, void* callData) {
  auto& messages = *static_cast<std::string*>(clientData);
  std::string message = callData != nullptr ? static_cast<const char*>(callData) : "VTK error";
  const std::size_t addressEnd = message.find("): ");  // drop "ERROR: In file, line\nclass (0x..)"
  if (addressEnd != std::string::npos) message.erase(0, addressEnd + 3);
  message.erase(std::min(message.find('\n'), message.size()));
  if (!messages.empty()) messages += "; ";
  messages += message;
}

const char* requiredAttribute(vtkXMLDataElement& dataSet, const char* name, int index) {
  const char* value = dataSet.GetAttribute(name);
  if (value == nullptr) {
    throw Error("DataSet " + std::to_string(index) + " has no '" + name + "' attribute");
  }
  return value;
}

double timeOf(const std::string& timeName, int index) {
  double time = 0;
  const char* end = timeName.data() + timeName.size();
  const auto [parsedEnd, error] = std::from_chars(timeName.data(), end, time);
  if (error != std::errc() || parsedEnd != end) {
    throw Error("DataSet " + std::to_string(index) + " has the timestep '" + timeName +
                "', which is not a number");
  }
  return time;
}

std::vector<PvdEntry> entriesOf(vtkXMLDataElement& root) {
  if (std::string(root.GetName()) != "VTKFile" || root.GetAttribute("type") == nullptr ||
      std::string(root.GetAttribute("type")) != "Collection") {
    throw Error("it is not a VTK Collection (<VTKFile type=\"Collection\">)");
  }
  vtkXMLDataElement* collection = root.FindNestedElementWithName("Collection");
  if (collection == nullptr) throw Error("it has no <Collection> element");
  std::vector<PvdEntry> entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement& dataSet = *collection->GetNestedElement(i);
    if (std::string(dataSet.GetName()) != "DataSet") continue;
    PvdEntry entry;
    entry.timeName = requiredAttribute(dataSet, "timestep", i);
    entry.time = timeOf(entry.timeName, i);
    entry.part = requiredAttribute(dataSet, "name", i);
    entry.file = requiredAttribute(dataSet, "file", i);
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace

void writePvd(const fs::path& pvdFile, std::vector<PvdEntry> entries) {
  writeFileAtomically(pvdFile, collectionXml(sortedUnique(std::move(entries))));
}

std::vector<PvdEntry> readPvd(const fs::path& pvdFile) {
  const std::string context = "cannot read ParaView index '" + pvdFile.string() + "': ";
  std::error_code ignored;
  if (!fs::is_regular_file(pvdFile, ignored)) {
    throw Error(context + (fs::exists(pvdFile, ignored) ? "not a regular file" : "no such file"));
  }
  std::string messages;
  vtkNew<vtkCallbackCommand> collector;
  collector->SetCallback(collectMessage);
  collector->SetClientData(&messages);
  vtkNew<vtkXMLDataParser> parser;
  parser->AddObserver(vtkCommand::ErrorEvent, collector);
  parser->AddObserver(vtkCommand::WarningEvent, collector);
  parser->SetFileName(pvdFile.c_str());
  const int parsed = parser->Parse();
  if (parsed == 0 || !messages.empty() || parser->GetRootElement() == nullptr) {
    throw Error(context + (messages.empty() ? "it is not well-formed XML" : messages));
  }
  try {
    return entriesOf(*parser->GetRootElement());
  } catch (const Error& error) {
    throw Error(context + error.what());
  }
}

}  // namespace sphcast
