// Table writers: one small interface, one file per format (exr_writer.cpp,
// binary_writer.cpp, cpp_header_writer.cpp). A writer writes exactly the
// path it is given; AtomicOutputSet (atomic_output.h) chooses temporary names
// and renames them only when every file of a bake has been written.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lutbake/core/error.h"
#include "lutbake/tables/storage.h"
#include "lutbake/tables/table.h"

namespace lutbake {

// How a generated header stores its values: float (exact float32, as the
// EXR and .bin hold them) or IEEE 754 half (binary16 bit patterns in
// std::uint16_t, rounded to nearest even: half the bytes, and an extra error
// the header states, at most 2^-12 = 2.4e-4 for values in [0, 1]).
enum class HeaderStorage { kFloat, kHalf };

struct WriteOptions {
  std::string headerNamespace = "lutbake_luts";
  HeaderStorage headerStorage = HeaderStorage::kFloat;
  // .bin values and error bounds: float32, or float64 for tables whose
  // integration bound is below what float32 can hold (--tolerance 1e-9).
  ValueType binaryValues = ValueType::kFloat32;
  // --format fit: the certified bound to reach (tables/table_fit.h: 4.9e-4,
  // half a binary16 ulp at 1, within 256 coefficients per channel).
  double fitTolerance = 4.9e-4;
};

// A value as half storage holds it: rounded to binary16 (nearest even) and
// widened back, exactly as the header's decoder returns it.
double RoundToHalf(double value);

class TableWriter {
 public:
  virtual ~TableWriter() = default;
  // "exr", "bin", "header", "png8", ...: the name used by --format.
  virtual const char *formatName() const = 0;
  // File extension including the dot: ".exr", ".bin", ".h".
  virtual const char *extension() const = 0;
  virtual void Write(const Table &table, const std::string &path,
                     const WriteOptions &options) const = 0;
};

std::unique_ptr<TableWriter> MakeExrWriter();
std::unique_ptr<TableWriter> MakeBinaryWriter();
std::unique_ptr<TableWriter> MakeCppHeaderWriter();
// --format png8 / png16 (png_table.cpp): bits 8 or 16.
std::unique_ptr<TableWriter> MakePngWriter(int bits);
// --format ktx2 / ktx2-half (ktx2_table.cpp): storage kFloat32 or kHalf.
std::unique_ptr<TableWriter> MakeKtx2Writer(ValueType storage);
// --format dds / dds-half (dds_table.cpp): storage kFloat32 or kHalf.
std::unique_ptr<TableWriter> MakeDdsWriter(ValueType storage);

// --format c-array (c_array_writer.cpp): T.h declaring static const float
// T[N] = {...}, as Blender Cycles' shader.tables does (engine presets).
std::unique_ptr<TableWriter> MakeCArrayWriter();
// --format threejs-dfg (threejs_module.cpp): a 2-channel table as three.js's
// DFGLUTData.js (half floats, getDFGLUT()), for the threejs preset.
std::unique_ptr<TableWriter> MakeThreejsDfgWriter();
std::unique_ptr<TableWriter> MakeThreejsLtcWriter();

// Throws IoError naming `path`, the table and the texel when a value is NaN
// or outside [0, 1]: `format` (e.g. "PNG") stores only that range.
void RequireUnitRange(const Table &table, const std::string &path, const char *format);

// Favg.h for a bake plan whose compensated materials all use Schlick's
// Fresnel: F_avg = 20/21 F0 + 1/21 F90 as inline functions (lookup_Favg(F0)
// and favg_schlick(F0, F90)), no table. `metadata` goes into its comment.
void WriteSchlickFavgHeader(const std::string &path, const WriteOptions &options,
                            const std::vector<std::pair<std::string, std::string>> &metadata);

// kulla_conty<suffix>.h, next to E<suffix>.h and Eavg<suffix>.h: the
// Kulla-Conty lobe f_ms<suffix>(mu_o, mu_i, r) and its Fresnel colour term
// fresnel_ms<suffix>(Favg, r), with the formulas stated in its comment.
void WriteKullaContyHeader(const std::string &path, const WriteOptions &options,
                           const std::string &suffix,
                           const std::vector<std::pair<std::string, std::string>> &metadata);

// The writer for a --format name, or nullptr.
std::unique_ptr<TableWriter> MakeWriter(const std::string &formatName);

}  // namespace lutbake
