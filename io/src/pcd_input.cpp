// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/pcd_input.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace floodplane::io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& reason) { throw std::runtime_error(reason); }

// PCL's reader logs its own multi-line complaints; the reader's exception says what went
// wrong in one line, so PCL is silenced while it reads and restored after.
class QuietPcl {
 public:
  QuietPcl() : previous_(pcl::console::getVerbosityLevel()) { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }
  ~QuietPcl() { pcl::console::setVerbosityLevel(previous_); }
  QuietPcl(const QuietPcl&) = delete;
  QuietPcl& operator=(const QuietPcl&) = delete;

 private:
  pcl::console::VERBOSITY_LEVEL previous_;
};

// PCL's reader trusts the sizes written in a binary file: a truncated binary_compressed file
// makes it read past the end of its memory map (a crash, not an error code). So the body's
// size is checked against the file's size here, from the header PCL has parsed, before PCL
// reads the body.
void checkBodySize(const std::string& path, std::uintmax_t file_size, int data_type, unsigned data_index,
                   const pcl::PCLPointCloud2& header) {
  const std::uint64_t body_size = std::uint64_t{header.width} * header.height * header.point_step;
  if (data_type == 1) {  // binary: the points, raw
    if (data_index + body_size > file_size) {
      fail("truncated PCD file: the header announces " + std::to_string(body_size) +
           " bytes of binary data, the file holds " + std::to_string(file_size - data_index));
    }
  } else if (data_type == 2) {  // binary_compressed: two uint32 sizes, then LZF data
    if (data_index + 8 > file_size) {
      fail("truncated PCD file: the compressed data is missing");
    }
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(data_index));
    std::uint32_t sizes[2] = {0, 0};
    in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
    if (!in) fail("cannot read the compressed data");
    const std::uint32_t compressed_size = sizes[0];
    const std::uint32_t uncompressed_size = sizes[1];
    if (data_index + 8 + std::uint64_t{compressed_size} > file_size) {
      fail("truncated PCD file: the header announces " + std::to_string(compressed_size) +
           " bytes of compressed data, the file holds " + std::to_string(file_size - data_index - 8));
    }
    if (uncompressed_size != body_size) {
      fail("corrupt PCD file: the compressed data unpacks to " + std::to_string(uncompressed_size) + " bytes, " +
           std::to_string(header.width) + " x " + std::to_string(header.height) + " points need " +
           std::to_string(body_size));
    }
  }
}

// A number of the header's SIZE, COUNT or POINTS line: PCL reads it with >> into an int or a
// size_t, which turns an overflowing or negative value into a huge size. One that is not all
// digits or exceeds INT_MAX is refused here. All digits: PCL's >> stops inside a word such as
// "0-465599" and reads the rest as the next value, -465599, a count of 4 G (found by
// fuzz_pcd_loader as an out-of-memory in PCL's readHeader).
std::uint64_t headerCount(const std::string& key, const std::string& word) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size() ||
      value > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    std::string shown = word.substr(0, 24);
    for (char& c : shown) c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    fail("corrupt PCD header: " + key + " value '" + shown + "' is not a count");
  }
  return value;
}

// What separates the words of a header line. PCL splits a line at spaces, tabs and carriage
// returns, but takes its first word with operator>>, which skips vertical tabs and form feeds
// too: with them here, "\vPOINTS" is a POINTS line as for PCL (and refused for its control
// character) rather than the end of the header.
constexpr const char* kHeaderSeparators = " \t\r\n\v\f";

// The words of a header line as PCL reads them.
std::vector<std::string> headerWords(const std::string& line) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start < line.size()) {
    const std::size_t end = std::min(line.find_first_of(kHeaderSeparators, start), line.size());
    if (end > start) words.push_back(line.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

// PCL's header loop (PCDReader::readHeader, 1.13), as far as the point buffer goes: it reads
// lines until one whose first word is no keyword, recognises a keyword by its prefix
// ("SIZEx" is a SIZE line), parses lines after DATA too, and allocates POINTS x the point
// size so far at every POINTS line.
class HeaderSizes {
 public:
  /// Takes one line; false when PCL's loop would stop at it. Where this could read a line
  /// otherwise than PCL (control characters, which PCL's word splitting and its >> treat
  /// differently; a SIZE or COUNT line that does not give one value per field), the file is
  /// refused: no valid header has them.
  bool add(const std::string& line, std::streamoff end_of_line) {
    if (line.empty() || line == "\n") return true;  // PCL skips empty lines
    std::vector<std::string> words = headerWords(line);
    if (words.empty()) return false;  // blanks only: no keyword, PCL stops
    const std::string key = words.front();
    words.erase(words.begin());
    const auto is = [&key](const char* keyword) { return key.rfind(keyword, 0) == 0; };
    if (is("#")) return true;
    const bool keyword = is("VERSION") || is("TYPE") || is("VIEWPOINT") || is("WIDTH") || is("HEIGHT") ||
                         is("FIELDS") || is("COLUMNS") || is("SIZE") || is("COUNT") || is("POINTS") || is("DATA");
    if (!keyword) return false;
    if (std::any_of(line.begin(), line.end(), [](char c) {
          const auto byte = static_cast<unsigned char>(c);
          return byte < 0x20 && c != '\t' && c != '\r' && c != '\n';
        })) {
      fail("corrupt PCD header: control characters in a header line");
    }
    if (is("FIELDS") || is("COLUMNS")) {
      sizes_.assign(words.size(), 4);
      counts_.assign(words.size(), 1);
    } else if (is("SIZE") || is("COUNT")) {
      if (words.size() != sizes_.size()) {
        fail(std::string("corrupt PCD header: ") + (is("SIZE") ? "SIZE" : "COUNT") + " gives " +
             std::to_string(words.size()) + " values for " + std::to_string(sizes_.size()) + " fields");
      }
      std::vector<std::uint64_t>& values = is("SIZE") ? sizes_ : counts_;
      for (std::size_t i = 0; i < words.size(); ++i) values[i] = headerCount(is("SIZE") ? "SIZE" : "COUNT", words[i]);
    } else if (is("POINTS")) {
      const std::uint64_t points = words.empty() ? 0 : headerCount("POINTS", words[0]);
      largest_buffer_ = std::max(largest_buffer_, points * pointStep());
    } else if (is("DATA")) {
      data_type_ = words.empty() ? "" : words[0];
      data_index_ = end_of_line;
    }
    return true;
  }

  /// Refuses a buffer that the file's body cannot fill.
  void check(std::uint64_t file_size) const {
    if (pointStep() > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      fail("corrupt PCD header: SIZE x COUNT gives points of " + std::to_string(pointStep()) + " bytes");
    }
    const std::uint64_t body = data_index_ > 0 && static_cast<std::uint64_t>(data_index_) <= file_size
                                   ? file_size - static_cast<std::uint64_t>(data_index_)
                                   : file_size;
    // An ASCII value takes at least two characters (a digit and a separator) and at most 8
    // bytes; LZF packs at most about 100:1 (a 3-byte back-reference repeats up to 264 bytes).
    const std::uint64_t expansion = data_type_.rfind("binary_compressed", 0) == 0 ? 100
                                    : data_type_.rfind("binary", 0) == 0          ? 1
                                                                                  : 4;
    if (largest_buffer_ > body * expansion) {
      fail("corrupt or truncated PCD file: the header announces " + std::to_string(largest_buffer_) +
           " bytes of points, the file's " + std::to_string(body) + " bytes of data cannot hold them");
    }
  }

 private:
  // Counts are below 2^31 and a line holds at most 64 Ki fields: no overflow.
  std::uint64_t pointStep() const {
    std::uint64_t step = 0;
    for (std::size_t i = 0; i < sizes_.size(); ++i) step += sizes_[i] * counts_[i];
    return step;
  }

  std::vector<std::uint64_t> sizes_;
  std::vector<std::uint64_t> counts_;
  std::uint64_t largest_buffer_ = 0;
  std::string data_type_;
  std::streamoff data_index_ = 0;
};

// PCL's readHeader allocates (and zero-fills) the point buffer the header announces before
// reading a byte of data, so a corrupt POINTS, SIZE or COUNT line can ask for terabytes
// (std::bad_alloc) or, worse, for a few gigabytes that are granted and swap the machine. This
// follows PCL's header loop and refuses a buffer that the file cannot fill; it only rejects,
// and leaves every other judgement of the header to PCL.
void checkAnnouncedSize(const std::string& path, std::uintmax_t file_size) {
  // A header is a few hundred bytes: the first 64 KiB hold it, or the file is refused.
  constexpr std::size_t kHeaderLimit = 65536;
  std::string start(static_cast<std::size_t>(std::min<std::uintmax_t>(file_size, kHeaderLimit)), '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(in.gcount()));
  HeaderSizes header;
  std::size_t line_start = 0;
  bool header_ended = false;
  while (line_start < start.size()) {
    std::size_t line_end = start.find('\n', line_start);
    if (line_end == std::string::npos && start.size() < file_size) {
      // The line goes on past the limit: a binary body after DATA without a newline byte in
      // the rest of the 64 KiB. PCL stops at it unless its first word starts with a keyword
      // (PCL compares prefixes), which the part read shows once it holds that word's first
      // kLongestKeyword characters or its end.
      constexpr std::size_t kLongestKeyword = 9;  // VIEWPOINT
      const std::string part = start.substr(line_start);
      const std::size_t word = part.find_first_not_of(kHeaderSeparators);
      const bool word_known = word == std::string::npos || part.size() - word >= kLongestKeyword ||
                              part.find_first_of(kHeaderSeparators, word) != std::string::npos;
      header_ended = word_known && !header.add(part, static_cast<std::streamoff>(start.size()));
      break;
    }
    line_end = line_end == std::string::npos ? start.size() : line_end + 1;
    if (!header.add(start.substr(line_start, line_end - line_start), static_cast<std::streamoff>(line_end))) {
      header_ended = true;
      break;
    }
    line_start = line_end;
  }
  if (!header_ended && start.size() < file_size) fail("corrupt PCD header: more than 64 KiB of header lines");
  header.check(file_size);
}

// PCL parses the header line by line, each line overriding what an earlier one said (and
// lines after DATA are parsed as header too), and reads the body with the result: a SIZE line
// after TYPE leaves a float in a 1-byte slot, a SIZE or COUNT line after POINTS leaves a
// buffer smaller than the points, and PCL then writes past the buffer. So every field must
// fit in its point with the size of its type, and the buffer must hold the points, before
// PCL reads a byte of the body. (Found by fuzz_pcd_loader as heap corruption.)
void checkLayout(const pcl::PCLPointCloud2& cloud) {
  for (const pcl::PCLPointField& field : cloud.fields) {
    const std::uint64_t size = pcl::getFieldSize(field.datatype);
    if (size == 0 || field.count == 0) {
      fail("corrupt PCD header: field " + field.name.substr(0, 24) + " has no valid SIZE, TYPE and COUNT");
    }
    if (std::uint64_t{field.offset} + std::uint64_t{field.count} * size > cloud.point_step) {
      fail("corrupt PCD header: field " + field.name.substr(0, 24) +
           " does not fit in its point (SIZE, TYPE and COUNT disagree)");
    }
  }
  if (cloud.data.size() != std::uint64_t{cloud.width} * cloud.height * cloud.point_step) {
    fail("corrupt PCD header: WIDTH x HEIGHT points of " + std::to_string(cloud.point_step) +
         " bytes do not match the POINTS line");
  }
}

// The file as PCL's untyped cloud, with its sensor pose, after every check that has to come
// before PCL reads the body.
struct RawCloud {
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
};

RawCloud readRawCloud(const std::string& path) {
  std::error_code error;
  const std::uintmax_t file_size = fs::file_size(path, error);
  if (error) fail("cannot read file: " + error.message());
  if (file_size == 0) fail("empty file, not a PCD file");
  // PCL's reader says "cannot read header" for a file it cannot open; say why instead.
  if (!std::ifstream(path, std::ios::binary)) fail(std::string("cannot open file: ") + std::strerror(errno));

  checkAnnouncedSize(path, file_size);

  const QuietPcl quiet;
  pcl::PCDReader reader;
  RawCloud raw;
  int version = 0;
  int data_type = 0;
  unsigned data_index = 0;
  try {
    if (reader.readHeader(path, raw.cloud, raw.origin, raw.orientation, version, data_type, data_index) < 0) {
      fail("not a PCD file, or its header is invalid");
    }
    // PCL 1.13's read() dereferences the first field without checking that there is one.
    if (raw.cloud.fields.empty() || raw.cloud.point_step == 0) {
      fail("not a PCD file, or its header is invalid (no fields)");
    }
    if (std::uint64_t{raw.cloud.width} * raw.cloud.height == 0) {
      fail("the cloud has no points (" + std::to_string(raw.cloud.width) + " x " + std::to_string(raw.cloud.height) +
           ")");
    }
    if (data_index > file_size) fail("truncated PCD file: the header is incomplete");
    checkLayout(raw.cloud);
    checkBodySize(path, file_size, data_type, data_index, raw.cloud);
    if (reader.read(path, raw.cloud, raw.origin, raw.orientation, version) < 0) {
      fail("corrupt or truncated PCD file (PCL cannot read its data)");
    }
  } catch (const pcl::PCLException& e) {
    fail(std::string("corrupt PCD file: ") + e.what());
  } catch (const std::runtime_error&) {
    throw;  // this reader's own reasons
  } catch (const std::bad_alloc&) {
    fail("corrupt PCD file: its header announces more points than fit in memory");
  } catch (const std::exception& e) {
    // PCL's header parser indexes the words of a line with at() and converts them with
    // boost::lexical_cast: a line with too few words or a bad number throws
    // std::out_of_range or boost::bad_lexical_cast, not its own exception.
    fail(std::string("not a PCD file, or its header is invalid (") + e.what() + ")");
  }
  return raw;
}

const pcl::PCLPointField* findField(const pcl::PCLPointCloud2& cloud, const std::string& name) {
  for (const auto& field : cloud.fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

// The fields the frame is made of; colour and label are null when the file has none (or
// none of a type read here).
struct FrameFields {
  const pcl::PCLPointField* x = nullptr;
  const pcl::PCLPointField* y = nullptr;
  const pcl::PCLPointField* z = nullptr;
  const pcl::PCLPointField* color = nullptr;
  const pcl::PCLPointField* label = nullptr;
};

// Checks that the cloud is an organized grid of 3-D points whose fields lie inside its points.
FrameFields checkedFields(const pcl::PCLPointCloud2& cloud) {
  for (const char* name : {"x", "y", "z"}) {
    const pcl::PCLPointField* field = findField(cloud, name);
    if (!field) fail("the cloud has no x y z fields (this method needs 3D points)");
    if (!(field->datatype == pcl::PCLPointField::FLOAT32 || field->datatype == pcl::PCLPointField::FLOAT64) ||
        field->count != 1) {
      fail(std::string("field ") + name + " is not a single float or double");
    }
  }
  if (cloud.height <= 1) {
    fail("unorganized cloud (" + std::to_string(cloud.width) + " x " + std::to_string(cloud.height) +
         "): this method needs an organized cloud (an image grid, height > 1)");
  }
  const std::size_t count = std::size_t{cloud.width} * cloud.height;
  if (cloud.data.size() < count * cloud.point_step) {
    fail("corrupt PCD file: " + std::to_string(cloud.data.size()) + " bytes of point data for " +
         std::to_string(count) + " points");
  }

  FrameFields fields{findField(cloud, "x"), findField(cloud, "y"), findField(cloud, "z"), findField(cloud, "rgb"),
                     findField(cloud, "label")};
  if (!fields.color) fields.color = findField(cloud, "rgba");
  // rgb is packed into 4 bytes whatever type the file declares (PCL writes F, others U).
  if (fields.color && !(fields.color->count == 1 && pcl::getFieldSize(fields.color->datatype) == 4)) {
    fields.color = nullptr;
  }
  if (fields.label && !(fields.label->count == 1 && fields.label->datatype == pcl::PCLPointField::UINT32)) {
    fields.label = nullptr;
  }
  for (const pcl::PCLPointField* field : {fields.x, fields.y, fields.z, fields.color, fields.label}) {
    if (field && field->offset + pcl::getFieldSize(field->datatype) > cloud.point_step) {
      fail("corrupt PCD file: field " + field->name + " lies outside the point");
    }
  }
  return fields;
}

// x, y, z may be stored as float or double (both occur in the wild); read either as float.
float readCoordinate(const std::uint8_t* point, const pcl::PCLPointField& field) {
  if (field.datatype == pcl::PCLPointField::FLOAT64) {
    double value;
    std::memcpy(&value, point + field.offset, sizeof(value));
    return static_cast<float>(value);
  }
  float value;
  std::memcpy(&value, point + field.offset, sizeof(value));
  return value;
}

std::uint32_t readUint32(const std::uint8_t* point, const pcl::PCLPointField& field) {
  std::uint32_t value;
  std::memcpy(&value, point + field.offset, sizeof(value));
  return value;
}

pcl::PointCloud<pcl::PointXYZ> xyzCloud(const RawCloud& raw, const FrameFields& fields) {
  const pcl::PCLPointCloud2& cloud = raw.cloud;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.resize(cloud.width, cloud.height);
  xyz.sensor_origin_ = raw.origin;
  xyz.sensor_orientation_ = raw.orientation;
  bool dense = true;
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    const std::uint8_t* point = cloud.data.data() + i * cloud.point_step;
    pcl::PointXYZ& p = xyz[i];
    p.x = readCoordinate(point, *fields.x);
    p.y = readCoordinate(point, *fields.y);
    p.z = readCoordinate(point, *fields.z);
    dense = dense && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  }
  xyz.is_dense = dense;
  return xyz;
}

pcl::PointCloud<pcl::PointXYZRGB> xyzrgbCloud(const pcl::PointCloud<pcl::PointXYZ>& xyz,
                                              const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& color) {
  pcl::PointCloud<pcl::PointXYZRGB> xyzrgb;
  xyzrgb.resize(cloud.width, cloud.height);
  xyzrgb.sensor_origin_ = xyz.sensor_origin_;
  xyzrgb.sensor_orientation_ = xyz.sensor_orientation_;
  xyzrgb.is_dense = xyz.is_dense;
  for (std::size_t i = 0; i < xyzrgb.size(); ++i) {
    pcl::PointXYZRGB& p = xyzrgb[i];
    p.getVector3fMap() = xyz[i].getVector3fMap();
    p.rgba = readUint32(cloud.data.data() + i * cloud.point_step, color);
  }
  return xyzrgb;
}

std::vector<std::uint32_t> labelGrid(const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& label) {
  std::vector<std::uint32_t> labels(std::size_t{cloud.width} * cloud.height);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    labels[i] = readUint32(cloud.data.data() + i * cloud.point_step, label);
  }
  return labels;
}

}  // namespace

InputFrame readPcdFrame(const std::string& path) {
  const RawCloud raw = readRawCloud(path);
  const FrameFields fields = checkedFields(raw.cloud);
  InputFrame frame;
  frame.xyz = xyzCloud(raw, fields);
  if (fields.color) frame.xyzrgb = xyzrgbCloud(frame.xyz, raw.cloud, *fields.color);
  if (fields.label) frame.labels = labelGrid(raw.cloud, *fields.label);
  return frame;
}

}  // namespace floodplane::io
