#include "models/ply_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <map>
#include <sstream>

#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

struct Property {
  std::string name;
  std::string type;        // the value's type
  std::string count_type;  // a list's count type ("" for a single value)
};

struct Element {
  std::string name;
  long long records = 0;
  std::vector<Property> properties;
};

struct Header {
  std::string format;  // ascii, binary_little_endian, binary_big_endian
  std::size_t bytes = 0;
  bool ended = false;  // end_header was found
  std::vector<Element> elements;
};

// Bytes of each PLY scalar type (both the 1.0 names and the sized ones); 0: unknown.
int type_bytes(const std::string& type) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},  {"uint8", 1},  {"short", 2},    {"ushort", 2},
      {"int16", 2}, {"uint16", 2}, {"int", 4},   {"uint", 4},   {"int32", 4},    {"uint32", 4},
      {"float", 4}, {"double", 8}, {"float32", 4}, {"float64", 8}};
  const auto size = sizes.find(type);
  return size == sizes.end() ? 0 : size->second;
}

// A header longer than 64 KiB is not a PLY header (the search for end_header stops there).
Header read_header(std::istream& in) {
  Header header;
  std::string line;
  while (std::getline(in, line) && header.bytes < (1u << 16)) {
    header.bytes += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "end_header") {
      header.ended = true;
      break;
    }
    if (word == "format") words >> header.format;
    if (word == "element") {
      header.elements.emplace_back();
      words >> header.elements.back().name >> header.elements.back().records;
    }
    if (word == "property" && !header.elements.empty()) {
      Property property;
      words >> property.type;
      if (property.type == "list") words >> property.count_type >> property.type;
      words >> property.name;
      header.elements.back().properties.push_back(property);
    }
  }
  return header;
}

// The colour channel (0, 1, 2) a face property holds, or -1.
int channel(const std::string& name) {
  if (name == "red" || name == "diffuse_red") return 0;
  if (name == "green" || name == "diffuse_green") return 1;
  if (name == "blue" || name == "diffuse_blue") return 2;
  return -1;
}

// An integer colour is a fraction of its type's largest value (PLY's convention, and Assimp's
// for vertex colours: uchar 255 is 1); a float is the fraction itself.
double colour_scale(const std::string& type) {
  if (type == "uchar" || type == "uint8") return 255.0;
  if (type == "char" || type == "int8") return 127.0;
  if (type == "ushort" || type == "uint16") return 65535.0;
  if (type == "short" || type == "int16") return 32767.0;
  if (type == "uint" || type == "uint32") return 4294967295.0;
  if (type == "int" || type == "int32") return 2147483647.0;
  return 1.0;
}

// Reads one binary value of `type` as a double, in the file's byte order.
bool read_binary(std::istream& in, const std::string& type, bool big_endian, double& value) {
  const int bytes = type_bytes(type);
  unsigned char raw[8];
  if (bytes == 0 || !in.read(reinterpret_cast<char*>(raw), bytes)) return false;
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  if ((first == 1) == big_endian)  // the host's order differs from the file's
    for (int i = 0; i < bytes / 2; ++i) std::swap(raw[i], raw[bytes - 1 - i]);
  const auto as = [&raw](auto v) { std::memcpy(&v, raw, sizeof v); return double(v); };
  if (type == "char" || type == "int8") return value = as(std::int8_t()), true;
  if (type == "uchar" || type == "uint8") return value = as(std::uint8_t()), true;
  if (type == "short" || type == "int16") return value = as(std::int16_t()), true;
  if (type == "ushort" || type == "uint16") return value = as(std::uint16_t()), true;
  if (type == "int" || type == "int32") return value = as(std::int32_t()), true;
  if (type == "uint" || type == "uint32") return value = as(std::uint32_t()), true;
  if (type == "float" || type == "float32") return value = as(float()), true;
  return value = as(double()), true;
}

bool read_value(std::istream& in, const Header& header, const std::string& type, double& value) {
  if (header.format == "ascii") return bool(in >> value);
  return read_binary(in, type, header.format == "binary_big_endian", value);
}

}  // namespace

void check_ply_length(const std::string& path) {
  InputStream in(path, kModelFile);
  const Header header = read_header(in);
  // Assimp 5.2 reads a header without end_header forever (a file cut in its header).
  if (!header.ended)
    throw InputError(path + ": the PLY header has no end_header line (within its first 64 KiB)");
  if (header.format != "ascii" && header.format != "binary_little_endian" &&
      header.format != "binary_big_endian")
    throw InputError(path + ": the PLY format \"" + header.format +
                     "\" is none of ascii, binary_little_endian, binary_big_endian");
  for (const Element& element : header.elements)
    if (element.records < 0 || element.records > (1LL << 40))  // sizes below stay far from overflow
      throw InputError(path + ": the PLY header declares " + std::to_string(element.records) + " " +
                       element.name + " records");
  long long records = 0, least_bytes = 0;
  std::string declared;
  for (const Element& element : header.elements) {
    long long record_bytes = 0;  // a list holds at least its count
    for (const Property& p : element.properties)
      record_bytes += type_bytes(p.count_type.empty() ? p.type : p.count_type);
    records += element.records;
    least_bytes += element.records * record_bytes;
    declared += (declared.empty() ? "" : ", ") + std::to_string(element.records) + " " + element.name;
  }
  std::string line;
  if (header.format == "ascii") {
    long long lines = 0;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t\r") != std::string::npos) ++lines;
    if (lines < records)
      throw InputError(path + ": the PLY header declares " + declared + " records, the file holds " +
                       std::to_string(lines) + " lines of data");
  } else {
    const long long body = (long long)in.file().size() - (long long)header.bytes;
    if (body < least_bytes)
      throw InputError(path + ": the PLY header declares " + declared + " records (at least " +
                       std::to_string(least_bytes) + " bytes), the file holds " +
                       std::to_string(body) + " bytes of data");
  }
}

std::vector<glm::dvec3> ply_face_colours(const std::string& path) {
  InputStream in(path, kModelFile);
  const Header header = read_header(in);
  std::vector<glm::dvec3> colours;
  // Faces without colours (the usual PLY) are not read here at all: Assimp reads them.
  int channels = 0;
  for (const Element& element : header.elements)
    if (element.name == "face")
      for (const Property& p : element.properties)
        if (channel(p.name) >= 0 && p.count_type.empty()) ++channels;
  if (channels == 0) return colours;
  if (channels != 3)
    throw InputError(path + ": the PLY faces have " + std::to_string(channels) +
                     " of the three colour properties red, green, blue");
  for (const Element& element : header.elements) {
    // Every element before the faces is read past (its records give no colours); an ASCII
    // record is a line, a binary one its values.
    for (long long r = 0; r < element.records; ++r) {
      glm::dvec3 colour(0.0);
      for (const Property& p : element.properties) {
        double value = 0.0;
        long long items = 1;
        if (!p.count_type.empty()) {
          if (!read_value(in, header, p.count_type, value) || !(value >= 0) || value > 1e9)
            throw InputError(path + ": " + element.name + " " + std::to_string(r) + ": the count of " +
                             p.name + " is missing or not a count");
          items = (long long)value;
        }
        for (long long i = 0; i < items; ++i)
          if (!read_value(in, header, p.type, value))
            throw InputError(path + ": " + element.name + " " + std::to_string(r) + ": " + p.name +
                             " is missing or not a number");
        if (element.name == "face" && p.count_type.empty() && channel(p.name) >= 0)
          colour[channel(p.name)] = value / colour_scale(p.type);
      }
      if (element.name == "face") colours.push_back(colour);
    }
    if (element.name == "face") return colours;
  }
  return colours;
}

}  // namespace ncube
