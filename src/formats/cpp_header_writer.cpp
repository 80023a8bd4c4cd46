// C++17 header output. The generated header includes only standard headers,
// uses no exceptions, and carries: the command line and version, the axis
// convention in a comment and as constexpr constants, the values printed with
// 9 significant digits (enough for any float to round-trip exactly), and an
// inline bilinear lookup with the texel-centre convention, clamped at the
// edges, that returns a texel's stored value exactly at its centre.
#include <Imath/half.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "file_io.h"
#include "format_list.h"
#include "lutbake/formats/writer.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

namespace {

// Appends value, rounded to float, as a float literal: 9 significant digits
// (%.9g: std::to_chars with a precision is specified to print as printf
// does, and is several times faster than snprintf), ".0" where that reads
// as an integer, and the suffix f.
void AppendFloatLiteral(double value, std::string *out) {
  char buffer[48];
  char *end =
      std::to_chars(buffer, buffer + sizeof buffer, static_cast<double>(static_cast<float>(value)),
                    std::chars_format::general, 9)
          .ptr;
  out->append(buffer, end);
  if (std::none_of(buffer, end, [](char c) { return c == '.' || c == 'e'; })) out->append(".0");
  out->push_back('f');
}

// A metadata value on one comment line: line breaks (a quoted argument of the
// command line may hold one) are written as \n and \r.
std::string OneLine(const std::string &text) {
  std::string s;
  for (const char c : text) s += c == '\n' ? "\\n" : c == '\r' ? "\\r" : std::string(1, c);
  return s;
}

// The "//   key: value" lines that open every generated header.
void WriteMetadataComment(std::ostream &h,
                          const std::vector<std::pair<std::string, std::string>> &metadata) {
  for (const auto &[key, value] : metadata) h << "//   " << key << ": " << OneLine(value) << "\n";
}

// A C++ string literal holding `text` exactly.
std::string StringLiteral(const std::string &text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      s += '\\';
      s += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\%03o", static_cast<unsigned>(c) & 0xffu);
      s += escaped;
    } else {
      s += c;
    }
  }
  return s + "\"";
}

std::string DoubleLiteral(double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  std::string s = buffer;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// The shared lookup helpers, emitted into each table's own namespace so that
// several generated headers can be included together.
const char *kCoordinateHelper =
    R"(// Continuous texel coordinate t = (v - lo) / (hi - lo) * n - 0.5 (t = i at
// the centre of texel i), clamped to [0, n - 1]; NaN maps to 0. A value
// within the float rounding of a texel centre is snapped onto it, so that
// a centre computed in float returns that texel's value exactly.
inline void Coordinate(float value, double lo, double hi, std::size_t n, std::size_t *i0,
                       double *weight) {
  double t = (static_cast<double>(value) - lo) / (hi - lo) * static_cast<double>(n) - 0.5;
  const double nearest = std::floor(t + 0.5);
  const double inputRounding = static_cast<double>(n) / (hi - lo) *
                               (std::fabs(lo) > std::fabs(hi) ? std::fabs(lo) : std::fabs(hi)) *
                               0x1p-23;
  if (std::fabs(t - nearest) <= inputRounding) t = nearest;
  if (!(t > 0.0)) t = 0.0;
  const double last = static_cast<double>(n - 1);
  if (t > last) t = last;
  std::size_t i = static_cast<std::size_t>(t);
  if (n > 1 && i > n - 2) i = n - 2;
  *i0 = i;
  *weight = n > 1 ? t - static_cast<double>(i) : 0.0;
}
)";

// Half storage: binary16 bit patterns decoded to float exactly, without
// exceptions or lookup tables.
const char *kHalfHelper =
    R"(// IEEE 754 binary16 to float: exact (every half is a float).
inline float HalfToFloat(std::uint16_t h) {
  const std::uint32_t sign = static_cast<std::uint32_t>(h & 0x8000u) << 16;
  std::uint32_t exponent = (h >> 10) & 0x1fu;
  std::uint32_t mantissa = h & 0x3ffu;
  std::uint32_t bits = sign;
  if (exponent == 0x1fu) {
    bits |= 0x7f800000u | (mantissa << 13);  // Inf, NaN (never written)
  } else if (exponent != 0) {
    bits |= ((exponent + 112u) << 23) | (mantissa << 13);
  } else if (mantissa != 0) {  // subnormal: mantissa 2^-24, normalised
    exponent = 113u;
    while ((mantissa & 0x400u) == 0) {
      mantissa <<= 1;
      --exponent;
    }
    bits |= (exponent << 23) | ((mantissa & 0x3ffu) << 13);
  }
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}
)";

// For listed axes (bake plans): the interval of `value` among increasing
// node values, linear in the value between neighbours, clamped outside.
const char *kNodeHelper =
    R"(// Listed axis: texel i holds the value at exactly nodes[i]; between two
// nodes the weight is linear in the value, outside them it clamps; NaN maps
// to the first node. A value within float rounding of a node is snapped
// onto it, so that the float a shader holds returns that row exactly.
inline void NodeCoordinate(float value, const double *nodes, std::size_t n, std::size_t *i0,
                           double *weight) {
  const double v = static_cast<double>(value);
  *i0 = 0;
  *weight = 0.0;
  if (n < 2 || !(v > nodes[0])) return;
  if (!(v < nodes[n - 1])) {
    *i0 = n - 2;
    *weight = 1.0;
    return;
  }
  std::size_t i = 0;
  while (nodes[i + 1] <= v) ++i;  // stops at i <= n - 2 because v < nodes[n - 1]
  *i0 = i;
  *weight = (v - nodes[i]) / (nodes[i + 1] - nodes[i]);
  if (std::fabs(v - nodes[i]) <= std::fabs(nodes[i]) * 0x1p-23) *weight = 0.0;
  if (std::fabs(v - nodes[i + 1]) <= std::fabs(nodes[i + 1]) * 0x1p-23) *weight = 1.0;
}
)";

class CppHeaderWriter final : public TableWriter {
 public:
  const char *formatName() const override { return "header"; }
  const char *extension() const override { return ".h"; }
  void Write(const Table &table, const std::string &path,
             const WriteOptions &options) const override {
    const std::string name = table.Name();
    const std::string ns = options.headerNamespace;
    const bool half = options.headerStorage == HeaderStorage::kHalf;
    // The most half storage moves a value, over this table (0 for float).
    double storageError = 0.0;
    if (half)
      for (double v : table.values)
        storageError = std::max(
            storageError, std::abs(RoundToHalf(v) - static_cast<double>(static_cast<float>(v))));
    // kErrorMax and the comment's errorMax: bounds of the values as this
    // header stores them (storage.h), the rounding to float32 or half included.
    const ValueType storage = half ? ValueType::kHalf : ValueType::kFloat32;
    std::ostringstream h;
    h << "// " << name << ".h: a lookup table generated by lutbake. Do not edit; regenerate.\n";
    WriteMetadataComment(h, MetadataForStorage(table, storage));
    h << "//   storage: "
      << (half ? "IEEE 754 half (binary16 in std::uint16_t), rounded to nearest even"
               : "float32, exactly the EXR and .bin values")
      << "\n";
    if (half) h << "//   storageErrorMax: " << DoubleLiteral(storageError) << "\n";
    h << "//\n// Texel convention: texel i of an axis of n texels holds the value at\n"
         "//   u = (i + 0.5) / n, axis value = min + (max - min) u.\n";
    const auto axisLine = [&](const char *which, const Axis &axis) {
      h << "// Axis " << which << axis.name;
      if (axis.listed()) {
        h << " listed at exactly";
        for (size_t i = 0; i < axis.nodes.size(); ++i) h << (i ? ", " : " ") << axis.nodes[i];
        h << " (" << axis.count << " texels; linear in " << axis.name << " between them).\n";
      } else {
        h << " in [" << axis.min << ", " << axis.max << "], " << axis.count << " texels.\n";
      }
    };
    axisLine("x (width):  ", table.x);
    if (table.is2D()) axisLine("y (height): ", table.y);
    const bool threeD = table.is3D();
    if (threeD) axisLine("z (depth):  ", table.z);
    const HeaderText notes = table.definition->Header(table);
    for (const std::string &note : notes.notes) h << "// " << note << "\n";
    h << (threeD ? "// Layout: kValues[((z * kHeight + y) * kWidth + x) * kChannels + c]"
                 : "// Layout: kValues[(y * kWidth + x) * kChannels + c]")
      << notes.layout;
    h << (threeD ? "// Lookups interpolate trilinearly between texel centres, clamp at the edges,\n"
                 : "// Lookups interpolate bilinearly between texel centres, clamp at the edges,\n")
      << "// and return a texel's value exactly at its centre.\n";
    h << "// kErrorMax bounds |value - truth| for every value as stored here, the\n"
         "// rounding to "
      << (half ? "half" : "float32") << " included.\n";
    if (half)
      h << "// Half storage alone moves a value by at most kStorageErrorMax (2^-12 = 2.4e-4\n"
           "// is the bound for values in [0, 1]; this table's own maximum is stated).\n";
    h << "#pragma once\n\n#include <array>\n#include <cmath>\n#include <cstddef>\n";
    if (half) h << "#include <cstdint>\n#include <cstring>\n";
    h << "\n";
    h << "namespace " << ns << " {\n\n";
    h << "namespace " << name << "_table {\n\n";
    h << "inline constexpr std::size_t kWidth = " << table.width() << ";\n";
    h << "inline constexpr std::size_t kHeight = " << table.height() << ";\n";
    if (threeD) h << "inline constexpr std::size_t kDepth = " << table.depth() << ";\n";
    h << "inline constexpr std::size_t kChannels = " << table.channels << ";\n";
    // The conventions as constants, for an engine to static_assert on
    // (std::string_view comparisons are constexpr from C++17).
    h << "// What the table holds and how it is laid out (also in the comment above).\n";
    const auto text = [&](const char *constant, const std::string &value) {
      h << "inline constexpr const char *" << constant << " = " << StringLiteral(value) << ";\n";
    };
    text("kTable", name);
    for (const auto &[key, constant] : {std::pair<const char *, const char *>{"ndf", "kNdf"},
                                        {"smith", "kSmith"},
                                        {"fresnel", "kFresnel"}})
      if (const std::string *value = table.FindMetadata(key)) text(constant, *value);
    const auto axisNames = [&](const char *which, const Axis &axis) {
      text((std::string("k") + which + "Axis").c_str(), axis.name);
      text((std::string("k") + which + "Mapping").c_str(), axis.listed() ? "listed" : "linear");
    };
    axisNames("X", table.x);
    if (table.is2D()) axisNames("Y", table.y);
    if (threeD) axisNames("Z", table.z);
    for (const std::string &constant : notes.constants) h << constant << "\n";
    h << "// Texel i of an axis of n texels holds the value at u = (i + kTexelCentre) / n.\n";
    h << "inline constexpr double kTexelCentre = 0.5;\n";
    h << "inline constexpr const char *kChannelNames[kChannels] = {";
    const std::vector<std::string> meanings = table.definition->ChannelMeanings();
    for (size_t c = 0; c < meanings.size(); ++c) h << (c ? ", " : "") << StringLiteral(meanings[c]);
    h << "};\n";
    if (const std::string *version = table.FindMetadata("lutbakeVersion"))
      text("kLutbakeVersion", *version);
    if (const std::string *commandLine = table.FindMetadata("commandLine"))
      text("kCommandLine", *commandLine);
    const auto axisConstants = [&](const char *which, const Axis &axis) {
      h << "inline constexpr double k" << which << "Min = " << DoubleLiteral(axis.min) << ";\n";
      h << "inline constexpr double k" << which << "Max = " << DoubleLiteral(axis.max) << ";\n";
      if (axis.listed()) {
        h << "inline constexpr double k" << which << "Nodes[" << axis.count << "] = {";
        for (size_t i = 0; i < axis.nodes.size(); ++i)
          h << (i ? ", " : "") << DoubleLiteral(axis.nodes[i]);
        h << "};\n";
      }
    };
    axisConstants("X", table.x);
    if (table.is2D()) axisConstants("Y", table.y);
    if (threeD) axisConstants("Z", table.z);
    const std::string size =
        threeD ? "kWidth * kHeight * kDepth * kChannels" : "kWidth * kHeight * kChannels";
    h << "inline constexpr double kErrorMax = "
      << DoubleLiteral(SummarizeStoredBounds(table, storage).max) << ";\n";
    if (half) {
      h << "inline constexpr double kStorageErrorMax = " << DoubleLiteral(storageError) << ";\n";
      h << "inline constexpr std::uint16_t kValues[" << size << "] = {";
      for (size_t i = 0; i < table.values.size(); ++i) {
        char bits[16];
        std::snprintf(
            bits, sizeof bits, "0x%04x",
            static_cast<unsigned>(Imath::half(static_cast<float>(table.values[i])).bits()));
        h << (i % 10 == 0 ? "\n    " : " ") << bits << (i + 1 < table.values.size() ? "," : "");
      }
    } else {
      h << "inline constexpr float kValues[" << size << "] = {";
      std::string values;
      values.reserve(18 * table.values.size());
      for (size_t i = 0; i < table.values.size(); ++i) {
        values += i % 6 == 0 ? "\n    " : " ";
        AppendFloatLiteral(table.values[i], &values);
        if (i + 1 < table.values.size()) values += ',';
      }
      h << values;
    }
    h << "};\n";
    h << "static_assert(sizeof(kValues) / sizeof(kValues[0]) == " << size << ",\n"
      << "              \"table size\");\n\n";
    h << kCoordinateHelper << "\n";
    if (half) h << kHalfHelper << "\n";
    if (table.x.listed() || (table.is2D() && table.y.listed()) || (threeD && table.z.listed()))
      h << kNodeHelper << "\n";
    // One generic sampler per channel count.
    h << "inline double Texel(std::size_t x, std::size_t y, std::size_t c) {\n"
         "  return static_cast<double>("
      << (half ? "HalfToFloat(kValues[(y * kWidth + x) * kChannels + c])"
               : "kValues[(y * kWidth + x) * kChannels + c]")
      << ");\n}\n\n";
    h << "inline double Sample(std::size_t x0, double wx, std::size_t y0, double wy, std::size_t "
         "c) {\n"
         "  const std::size_t x1 = kWidth > 1 ? x0 + 1 : x0;\n"
         "  const std::size_t y1 = kHeight > 1 ? y0 + 1 : y0;\n"
         "  return (1.0 - wy) * ((1.0 - wx) * Texel(x0, y0, c) + wx * Texel(x1, y0, c)) +\n"
         "         wy * ((1.0 - wx) * Texel(x0, y1, c) + wx * Texel(x1, y1, c));\n}\n\n";
    if (threeD) {
      // Slice z of a 3D table is a 2D table at offset z * kWidth * kHeight.
      h << "inline double Texel3(std::size_t x, std::size_t y, std::size_t z, std::size_t c) {\n"
           "  return Texel(x, z * kHeight + y, c);\n}\n\n";
      h << "inline double Sample3(std::size_t x0, double wx, std::size_t y0, double wy, "
           "std::size_t z0,\n"
           "                       double wz, std::size_t c) {\n"
           "  const std::size_t z1 = kDepth > 1 ? z0 + 1 : z0;\n"
           "  return (1.0 - wz) * Sample(x0, wx, z0 * kHeight + y0, wy, c) +\n"
           "         wz * Sample(x0, wx, z1 * kHeight + y0, wy, c);\n}\n\n";
    }
    h << "}  // namespace " << name << "_table\n\n";

    const std::string px = table.x.name;
    const std::string py = table.is2D() ? table.y.name : "";
    const std::string pz = threeD ? table.z.name : "";
    const std::string t = name + "_table::";
    std::string signature, body;
    body = "  std::size_t x0 = 0, y0 = 0;\n  double wx = 0.0, wy = 0.0;\n";
    const auto coordinate = [&](const Axis &axis, const std::string &param, const char *which,
                                const char *count, const char *out) {
      if (axis.listed())
        return "  " + t + "NodeCoordinate(" + param + ", " + t + "k" + which + "Nodes, " + t +
               count + ", " + out + ");\n";
      return "  " + t + "Coordinate(" + param + ", " + t + "k" + which + "Min, " + t + "k" + which +
             "Max, " + t + count + ", " + out + ");\n";
    };
    body += coordinate(table.x, px, "X", "kWidth", "&x0, &wx");
    if (table.is2D()) body += coordinate(table.y, py, "Y", "kHeight", "&y0, &wy");
    h << "// " << notes.lookupComment << "\n";
    if (threeD) {
      body += "  std::size_t z0 = 0;\n  double wz = 0.0;\n" +
              coordinate(table.z, pz, "Z", "kDepth", "&z0, &wz");
      const auto sample = [&](int c) {
        return "static_cast<float>(" + t + "Sample3(x0, wx, y0, wy, z0, wz, " + std::to_string(c) +
               "))";
      };
      if (table.channels >= 2) {
        h << "inline std::array<float, " << table.channels << "> lookup_" << name << "(float " << px
          << ", float " << py << ", float " << pz << ") {\n"
          << body << "  return {" << sample(0);
        for (int c = 1; c < table.channels; ++c) h << ",\n          " << sample(c);
        h << "};\n}\n\n";
      } else {
        h << "inline float lookup_" << name << "(float " << px << ", float " << py << ", float "
          << pz << ") {\n"
          << body << "  return " << sample(0) << ";\n}\n\n";
      }
    } else if (table.channels >= 2) {
      h << "inline std::array<float, " << table.channels << "> lookup_" << name << "(float " << px
        << ", float " << py << ") {\n"
        << body << "  return {static_cast<float>(" << t << "Sample(x0, wx, y0, wy, 0))";
      for (int c = 1; c < table.channels; ++c)
        h << ",\n          static_cast<float>(" << t << "Sample(x0, wx, y0, wy, " << c << "))";
      h << "};\n}\n\n";
    } else {
      h << "inline float lookup_" << name << "(float " << px
        << (table.is2D() ? ", float " + py : std::string()) << ") {\n"
        << body << "  return static_cast<float>(" << t << "Sample(x0, wx, y0, wy, 0));\n}\n\n";
    }
    if (notes.helpers) h << notes.helpers("lookup_" + name);
    h << "}  // namespace " << ns << "\n";
    WriteWholeFile(path, h.str());
  }
};

}  // namespace

double RoundToHalf(double value) { return StoredValue(value, ValueType::kHalf); }

void WriteSchlickFavgHeader(const std::string &path, const WriteOptions &options,
                            const std::vector<std::pair<std::string, std::string>> &metadata) {
  std::ostringstream h;
  h << "// Favg.h: average Fresnel by a closed form, generated by lutbake. Do not edit; "
       "regenerate.\n";
  WriteMetadataComment(h, metadata);
  h << "//\n"
       "// Every material of the plan that uses energy compensation has Schlick's Fresnel\n"
       "//   F(mu) = F0 + (F90 - F0) (1 - mu)^5,\n"
       "// whose average F_avg = 2 integral_0^1 F(mu) mu dmu is exactly\n"
       "//   F0 + (F90 - F0) 2 integral_0^1 (1 - mu)^5 mu dmu = F0 + (F90 - F0) / 21\n"
       "//   = 20/21 F0 + 1/21 F90,\n"
       "// so this header carries that function and no table. lookup_Favg(F0) is the\n"
       "// F90 = 1 case, with the same signature as a Favg table's header.\n"
       "#pragma once\n\n";
  h << "namespace " << options.headerNamespace << " {\n\n";
  h << "inline float favg_schlick(float F0, float F90) {\n"
       "  return static_cast<float>(static_cast<double>(F0) * (20.0 / 21.0) +\n"
       "                            static_cast<double>(F90) * (1.0 / 21.0));\n}\n\n";
  h << "inline float lookup_Favg(float F0) { return favg_schlick(F0, 1.0f); }\n\n";
  h << "}  // namespace " << options.headerNamespace << "\n";
  WriteWholeFile(path, h.str());
}

void WriteKullaContyHeader(const std::string &path, const WriteOptions &options,
                           const std::string &suffix,
                           const std::vector<std::pair<std::string, std::string>> &metadata) {
  const std::string e = "E" + suffix, eavg = "Eavg" + suffix;
  std::ostringstream h;
  h << "// kulla_conty" << suffix << ".h: Kulla-Conty multiple-scattering helpers over " << e
    << ".h and " << eavg << ".h,\n// generated by lutbake. Do not edit; regenerate.\n";
  WriteMetadataComment(h, metadata);
  h << "//\n"
       "// A single-scattering microfacet BRDF f reflects E(mu_o, r) of the light\n"
       "// (F = 1) and loses 1 - E to the paths that bounce between microfacets.\n"
       "// Kulla and Conty (2017) add back the lobe\n"
       "//   f_ms(mu_o, mu_i, r) = (1 - E(mu_o, r)) (1 - E(mu_i, r)) / (pi (1 - E_avg(r))),\n"
       "// with E_avg(r) = 2 integral_0^1 E(mu, r) mu dmu. Since\n"
       "//   integral f_ms mu_i d(omega_i) = (1 - E(mu_o)) 2 integral_0^1 (1 - E(mu_i)) mu_i "
       "dmu_i\n"
       "//                                    / (1 - E_avg) = 1 - E(mu_o),\n"
       "// f + f_ms passes the white furnace: E(mu_o) + integral f_ms cos = 1.\n"
       "// With a Fresnel term, multiply f_ms, per colour channel, by\n"
       "//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),\n"
       "// the light that leaves after any number of bounces, each reflecting F_avg\n"
       "// and escaping with E_avg (F_avg from Favg.h, or 20/21 F0 + 1/21 F90 for\n"
       "// Schlick). mu are cosines to the normal in [0, 1]; r is perceptual\n"
       "// roughness (alpha = r^2), as in the table lookups.\n"
       "#pragma once\n\n";
  h << "#include \"" << e << ".h\"\n#include \"" << eavg << ".h\"\n\n";
  h << "namespace " << options.headerNamespace << " {\n\n";
  h << "// The multiple-scattering lobe f_ms (per steradian, F = 1). 0 where E_avg\n"
       "// rounds to 1 (the mirror has no multiple scattering), never NaN.\n";
  h << "inline float f_ms" << suffix << "(float mu_o, float mu_i, float r) {\n"
    << "  const double eavg = static_cast<double>(lookup_" << eavg << "(r));\n"
    << "  const double lost = 1.0 - eavg;\n"
    << "  if (!(lost > 0.0)) return 0.0f;\n"
    << "  const auto escape = [](float e) {\n"
    << "    const double v = 1.0 - static_cast<double>(e);\n"
    << "    return v > 0.0 ? v : 0.0;\n"
    << "  };\n"
    << "  return static_cast<float>(escape(lookup_" << e << "(mu_o, r)) * escape(lookup_" << e
    << "(mu_i, r)) /\n"
    << "                            (3.14159265358979323846 * lost));\n"
    << "}\n\n";
  h << "// The Fresnel colour of the multiple-scattering lobe, for one channel:\n"
       "// F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), with E_avg = lookup_"
    << eavg
    << "(r).\n"
       "// F_avg is clamped to [0, 1]; the denominator is then at least E_avg > 0.\n";
  h << "inline float fresnel_ms" << suffix << "(float Favg, float r) {\n"
    << "  const double eavg = static_cast<double>(lookup_" << eavg << "(r));\n"
    << "  const double f = Favg > 1.0f ? 1.0 : (Favg > 0.0f ? static_cast<double>(Favg) : 0.0);\n"
    << "  const double denominator = 1.0 - f * (1.0 - eavg);\n"
    << "  return denominator > 0.0 ? static_cast<float>(f * f * eavg / denominator) : 0.0f;\n"
    << "}\n\n";
  h << "}  // namespace " << options.headerNamespace << "\n";
  WriteWholeFile(path, h.str());
}

std::unique_ptr<TableWriter> MakeCppHeaderWriter() { return std::make_unique<CppHeaderWriter>(); }

std::vector<TableFormat> CppHeaderFormats() {
  return {{"header",
           ".h",
           [](const WriteOptions &o) {
             return o.headerStorage == HeaderStorage::kHalf ? ValueType::kHalf
                                                            : ValueType::kFloat32;
           },
           MakeCppHeaderWriter,
           {},
           true,
           false,
           kMaxTableChannels}};
}

}  // namespace lutbake
