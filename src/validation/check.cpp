#include "lutbake/validation/check.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "lutbake/core/hash.h"
#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/format.h"
#include "lutbake/formats/table_reader.h"
#include "lutbake/formats/writer.h"
#include "lutbake/integrators/fresnel_average.h"
#include "lutbake/tables/lookup.h"
#include "lutbake/tables/set_claim.h"
#include "lutbake/validation/fit_check.h"

namespace lutbake {

bool CheckReport::passed() const {
  for (const CheckResult &r : results)
    if (r.status == CheckStatus::kFail) return false;
  return true;
}

namespace {

namespace fs = std::filesystem;

using namespace claim_text;

// A table as read from DIR, with everything the checks need (set_claim.h).
using Loaded = CheckedTable;

// A .bin written with --bin-type double (errorStorage=float64).
bool BinIsFloat64(const Table &bin) {
  const std::string *storage = bin.FindMetadata("errorStorage");
  return storage && *storage == "float64";
}

// The texel indices of flat texel number `texel` (x inner, then y, then z).
struct TexelIndex {
  int x, y, z;
};
TexelIndex IndexOf(const Table &t, size_t texel) {
  const size_t slice = static_cast<size_t>(t.width()) * t.height();
  return {static_cast<int>(texel % t.width()), static_cast<int>((texel % slice) / t.width()),
          static_cast<int>(texel / slice)};
}

// Where a texel's centre is, named by the table's axes.
std::vector<std::pair<std::string, double>> AtTexel(const Table &t, size_t texel) {
  const TexelIndex i = IndexOf(t, texel);
  return At(t, t.x.TexelCenter(i.x), t.y.TexelCenter(i.y), t.z.TexelCenter(i.z));
}

// The engine's lookup (bilinear, trilinear for a 3D table) of channel c.
double LookupAt(const Table &t, const std::vector<double> &values, double x, double y, double z,
                int c) {
  return t.is3D() ? Lookup(t, values, x, y, z, c) : Lookup(t, values, x, y, c);
}

class Checker final : public ClaimContext {
 public:
  // suffix: "" for E, Eavg, Favg, dfg; "_beckmann" for E_beckmann, ...
  Checker(const std::string &dir, const CheckOptions &options, std::string suffix)
      : dir_(dir), options_(options), suffix_(std::move(suffix)) {}

  CheckReport Run() {
    const auto start = std::chrono::steady_clock::now();
    report_.dir = dir_;
    for (size_t i = 0; i < AllTables().size(); ++i) Load(i);
    if (tables_.empty()) {
      Add(dir_, "tables", CheckStatus::kFail,
          "no table files (" + TableNameList() +
              " as .exr, .bin, .h, .ktx2, .dds, .png or a source embedding) found in " + dir_);
    } else {
      ComputeReferences();
      for (auto &[index, t] : tables_) {
        if (!t.usable) continue;
        CheckFinite(t);
        CheckRange(t);
        CheckTexels(t);
        CheckIndependent(t);
        CheckPoints(t);
        CheckMonotonic(t);
        CheckClosedForm(t);
        CheckSliceClosedForm(t);
        CheckLimits(t);
        if (t.def->FittedChannels() > 0) CheckFit(t);
      }
      // The claims the definitions make with other tables of the set
      // (set_claim.h), by order, then by table.
      std::vector<std::pair<const SetClaim *, const Loaded *>> claims;
      std::vector<std::shared_ptr<const SetClaim>> owned;
      for (auto &[index, t] : tables_)
        for (std::shared_ptr<const SetClaim> &claim : t.def->Claims()) {
          claims.emplace_back(claim.get(), &t);
          owned.push_back(std::move(claim));
        }
      std::stable_sort(claims.begin(), claims.end(), [](const auto &a, const auto &b) {
        return a.first->Order() < b.first->Order();
      });
      for (const auto &[claim, t] : claims) claim->Judge(*t, *this);
    }
    report_.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report_;
  }

  // ---- the set, as the claims see it (ClaimContext) ---------------------

  // The usable table of this set whose definition is called `name`.
  const Loaded *Usable(const std::string &name) const override {
    for (const auto &[index, t] : tables_)
      if (t.usable && name == t.def->Name()) return &t;
    return nullptr;
  }
  const std::string &Suffix() const override { return suffix_; }
  // Same model, or a failed check that says they differ.
  bool SameModel(const Loaded &a, const Loaded &b, const std::string &subject,
                 const std::string &check) override {
    if (a.def->SameModel(a.model, b.model)) return true;
    Add(subject, check, CheckStatus::kFail,
        Name(*a.def) + " is " + a.def->DescribeModel(a.model) + " but " + Name(*b.def) + " is " +
            b.def->DescribeModel(b.model) + ": the set mixes models");
    return false;
  }
  void Add(const std::string &subject, const std::string &check, ClaimStatus status,
           const std::string &detail, double worst, double allowed, ClaimPlace at) override {
    Add(subject, check,
        status == ClaimStatus::kPass   ? CheckStatus::kPass
        : status == ClaimStatus::kFail ? CheckStatus::kFail
                                       : CheckStatus::kSkipped,
        detail, worst, allowed, std::move(at));
  }
  int FurnaceGrid() const override { return options_.furnaceGrid; }
  const std::vector<ReferencePoint> &Grid(const Loaded &t) const override {
    return scalingGrid_.at(t.index);
  }

 private:
  void Add(const std::string &subject, const std::string &check, CheckStatus status,
           const std::string &detail, double worst = 0.0, double allowed = 0.0,
           std::vector<std::pair<std::string, double>> at = {}) {
    report_.results.push_back({subject, check, status, detail, worst, allowed, std::move(at)});
  }

  // ---- reading ---------------------------------------------------------

  static bool IsClosedFormHeader(const std::string &path) {
    std::ifstream file(path);
    for (std::string line; file && std::getline(file, line) && line.rfind("//", 0) == 0;)
      if (line.rfind("//   content: closed form (Schlick), no table", 0) == 0) return true;
    return false;
  }

  void Load(size_t index) {
    const TableDefinition &def = *AllTables()[index];
    const std::string name = Name(def);
    const fs::path base = fs::path(dir_) / name;
    const std::string exrPath = base.string() + ".exr", binPath = base.string() + ".bin",
                      hPath = base.string() + ".h", errPath = base.string() + ".err.exr";
    const std::string pngPath = base.string() + ".png", ktx2Path = base.string() + ".ktx2",
                      ddsPath = base.string() + ".dds";
    std::optional<Table> exr, bin, err, png, ktx2, dds;
    std::optional<HeaderValues> header;
    std::vector<std::string> problems;
    const auto attempt = [&](const std::string &path, auto read) {
      std::error_code ec;
      if (!fs::exists(path, ec)) return;
      try {
        read();
        report_.files.push_back(path);
      } catch (const IoError &e) {
        problems.push_back(e.what());
      }
    };
    // A bake plan whose compensated materials all use Schlick writes Favg.h
    // with the closed form and no table (plan.h): nothing numeric to check.
    if (IsClosedFormHeader(hPath)) {
      report_.files.push_back(hPath);
      Add(name, "closed form", CheckStatus::kPass,
          hPath + ": Schlick's closed form F_avg = 20/21 F0 + 1/21 F90, no table (a bake plan's)");
      return;
    }
    attempt(exrPath, [&] { exr = ReadExrTable(exrPath); });
    attempt(binPath, [&] { bin = ReadBinaryTable(binPath); });
    attempt(hPath, [&] { header = ReadHeaderValues(hPath); });
    attempt(errPath, [&] { err = ReadExrTable(errPath); });
    attempt(ktx2Path, [&] { ktx2 = ReadKtx2Table(ktx2Path); });
    attempt(ddsPath, [&] { dds = ReadDdsTable(ddsPath); });
    attempt(pngPath, [&] { png = ReadPngTable(pngPath); });
    // The source embeddings (format.h's sourceText formats that bake
    // writes), float32 or half: one file per extension.
    std::vector<std::pair<std::string, std::optional<Table>>> sources;
    std::vector<std::string> extensions;  // in the registry's order
    for (const TableFormat &format : AllFormats())
      if (format.bakeFormat && format.sourceText &&
          std::find(extensions.begin(), extensions.end(), format.extension) == extensions.end())
        extensions.push_back(format.extension);
    for (const std::string &extension : extensions) {
      const std::string path = base.string() + extension;
      std::optional<Table> source;
      attempt(path, [&] { source = ReadSourceTable(path); });
      if (source) sources.emplace_back(path, std::move(source));
    }
    const bool present =
        exr || bin || header || ktx2 || dds || png || !sources.empty() || !problems.empty();
    if (!present) return;
    Loaded &t = tables_[index];
    t.def = &def;
    t.index = index;
    for (const std::string &p : problems) Add(name, "metadata", CheckStatus::kFail, p);

    // The primary file: EXR, else .bin, else the header (whose metadata
    // comment carries the axes).
    if (exr) {
      t.table = *exr;
      t.primary = exrPath;
    } else if (bin) {
      t.table = *bin;
      t.primary = binPath;
    } else if (header) {
      t.primary = hPath;
      t.table.metadata = header->metadata;
      t.table.channels = header->channels;
      t.table.values.assign(header->values.begin(), header->values.end());
      const std::string *ax = t.table.FindMetadata("axisX"), *ay = t.table.FindMetadata("axisY");
      bool ok = ax && ParseAxisDescription(*ax, &t.table.x);
      if (ay && !ParseAxisDescription(*ay, &t.table.y)) t.table.y = LinearAxis("", 0.0, 1.0, 1);
      if (const std::string *az = t.table.FindMetadata("axisZ"))
        ok = ok && ParseAxisDescription(*az, &t.table.z) && !t.table.z.name.empty();
      ok = ok && t.table.x.count == header->width && t.table.y.count == header->height &&
           t.table.z.count == header->depth;
      if (!ok) {
        Add(name, "metadata", CheckStatus::kFail,
            hPath + ": its comment lacks axisX / axisY matching kWidth and kHeight");
        return;
      }
    } else if (!ktx2 && !dds && !png && !sources.empty()) {
      // Only source embeddings: a float32 one if there is one.
      const auto chosen = std::find_if(sources.begin(), sources.end(), [](const auto &f) {
        return *f.second->FindMetadata("errorStorage") == "float32";
      });
      const auto &[path, file] = chosen != sources.end() ? *chosen : sources.front();
      t.table = *file;
      t.primary = path;
      t.halfStorage = *file->FindMetadata("errorStorage") == "half";
      t.storageError = t.halfStorage ? 0x1p-12 : 0.0;
    } else if (ktx2 || dds || png) {
      // The GPU texture files, the most precise first; their metadata
      // (errorStorage) makes errorMax cover their own storage.
      const auto storage = [](const std::optional<Table> &f) {
        return f ? *f->FindMetadata("errorStorage") : std::string();  // the readers require it
      };
      const bool ktx2Float = storage(ktx2) == "float32", ddsFloat = storage(dds) == "float32";
      const bool useKtx2 = ktx2 && (ktx2Float || !ddsFloat), useDds = !useKtx2 && dds;
      t.table = useKtx2 ? *ktx2 : useDds ? *dds : *png;
      t.primary = useKtx2 ? ktx2Path : useDds ? ddsPath : pngPath;
      // What the storage may move a value in [0, 1] (the range check's
      // slack for sums; errorMax covers it already): half an ulp of half at
      // [0.5, 1), 2^-12, or half a b-bit step.
      const std::string kind = storage(useKtx2 ? ktx2 : useDds ? dds : png);
      t.halfStorage = kind == "half";
      t.storageError = kind == "half"      ? 0x1p-12
                       : kind == "unorm8"  ? 0.5 / 255.0
                       : kind == "unorm16" ? 0.5 / 65535.0
                                           : 0.0;
    } else {
      return;  // nothing readable; the reasons are reported above
    }
    if (!CheckMetadata(t)) return;
    // A half-storage header as the primary file: its values carry the
    // storage rounding too, which the header states (storageErrorMax).
    if (!exr && !bin && header && header->half) {
      const std::string *storage = t.table.FindMetadata("storageErrorMax");
      char *end = nullptr;
      const double extra = storage ? std::strtod(storage->c_str(), &end) : -1.0;
      if (!storage || *end != '\0' || !(extra >= 0.0 && extra <= 1.0)) {
        Add(name, "metadata", CheckStatus::kFail,
            hPath + ": half storage without a valid storageErrorMax");
        return;
      }
      t.storageError = extra;
      // Older headers stated errorMax for the float values; the half rounding
      // is theirs to add. Now kErrorMax covers it (errorStorage=half).
      if (!t.boundsCoverStorage) t.statedErrorMax += extra;
    }
    // Per-texel bounds: the .bin error block, else T.err.exr. A float64 .bin
    // bounds its own values: for the primary's, its rounding is added.
    if (bin && bin->errors.size() == t.table.values.size()) {
      t.table.errors = bin->errors;
      if (BinIsFloat64(*bin))
        for (size_t i = 0; i < t.table.errors.size(); ++i)
          t.table.errors[i] += std::abs(t.table.values[i] - bin->values[i]);
      t.perTexelErrors = true;
    } else if (err && err->values.size() == t.table.values.size()) {
      t.table.errors = err->values;
      t.perTexelErrors = true;
    } else {
      t.table.errors.assign(t.table.values.size(), t.statedErrorMax);
    }
    CheckFormats(t, exr, bin, header, err);
    std::vector<std::pair<std::string, std::optional<Table>>> textures = {
        {ktx2Path, ktx2}, {ddsPath, dds}, {pngPath, png}};
    textures.insert(textures.end(), sources.begin(), sources.end());
    CheckTextureFormats(t, textures);
    t.usable = true;
  }

  // The metadata: the table lutbake claims to have written. False when the
  // numeric checks cannot run on it.
  bool CheckMetadata(Loaded &t) {
    const std::string name = Name(*t.def);
    Table &table = t.table;
    std::vector<std::string> problems;
    const auto meta = [&](const std::string &key) {
      return RequiredMetadata(table, key, &problems);
    };
    if (meta("table") != t.def->Name())
      problems.push_back("table is not '" + std::string(t.def->Name()) + "'");
    const int channels = t.def->Channels();
    if (table.channels != channels)
      problems.push_back(std::to_string(table.channels) + " channels, expected " +
                         std::to_string(channels));
    t.boundsCoverStorage = table.FindMetadata("errorStorage") != nullptr;
    const std::string errorMax = meta("errorMax");
    char *end = nullptr;
    t.statedErrorMax = std::strtod(errorMax.c_str(), &end);
    if (errorMax.empty() || *end != '\0' || !(t.statedErrorMax >= 0.0) ||
        !std::isfinite(t.statedErrorMax))
      problems.push_back("errorMax '" + errorMax + "' is not a non-negative number");
    if (meta("texelConvention").rfind("texel i of N holds the value at u = (i + 0.5) / N", 0) != 0)
      problems.push_back("texelConvention is not lutbake's (texel centres)");
    t.def->ReadModel(table, &t.model, &problems);
    if (!problems.empty()) {
      std::string detail = t.primary + ": ";
      for (size_t i = 0; i < problems.size(); ++i) detail += (i ? "; " : "") + problems[i];
      Add(name, "metadata", CheckStatus::kFail, detail);
      return false;
    }
    const std::string model = t.def->DescribeModel(t.model);
    Add(name, "metadata", CheckStatus::kPass,
        t.primary + ": " + std::to_string(table.width()) + " x " + std::to_string(table.height()) +
            (table.is3D() ? " x " + std::to_string(table.depth()) : "") + ", " + model + ", " +
            DescribeAxis(table.x) + (table.is2D() ? " x " + DescribeAxis(table.y) : "") +
            (table.is3D() ? " x " + DescribeAxis(table.z) : "") + ", errorMax " +
            Short(t.statedErrorMax));
    return true;
  }

  // Every format present holds the primary's numbers, bit for bit as float32,
  // and the same axes.
  void CheckFormats(const Loaded &t, const std::optional<Table> &exr,
                    const std::optional<Table> &bin, const std::optional<HeaderValues> &header,
                    const std::optional<Table> &err) {
    const std::string name = Name(*t.def);
    std::vector<std::string> compared, problems;
    const auto sameValues = [&](const std::vector<double> &a, const std::string &what,
                                bool half = false) {
      if (a.size() != t.table.values.size()) {
        problems.push_back(what + " has " + std::to_string(a.size()) + " values, " + t.primary +
                           " " + std::to_string(t.table.values.size()));
        return;
      }
      for (size_t i = 0; i < a.size(); ++i)
        if (static_cast<float>(a[i]) !=
                static_cast<float>(half ? RoundToHalf(t.table.values[i]) : t.table.values[i]) &&
            !(std::isnan(a[i]) && std::isnan(t.table.values[i]))) {
          const int c = static_cast<int>(i % t.table.channels);
          const TexelIndex at = IndexOf(t.table, i / t.table.channels);
          problems.push_back(what + " differs at texel (" + std::to_string(at.x) + ", " +
                             std::to_string(at.y) +
                             (t.table.is3D() ? ", " + std::to_string(at.z) : std::string()) +
                             ") channel " + std::to_string(c) + ": " + FormatDouble(a[i]) +
                             " against " + FormatDouble(t.table.values[i]));
          return;
        }
      compared.push_back(what);
    };
    const auto sameAxes = [&](const Table &other, const std::string &what) {
      if (DescribeAxis(other.x) != DescribeAxis(t.table.x) ||
          (t.table.is2D() && DescribeAxis(other.y) != DescribeAxis(t.table.y)) ||
          DescribeAxis(other.z) != DescribeAxis(t.table.z))
        problems.push_back(what + " has other axes than " + t.primary);
    };
    if (bin && exr) {
      sameAxes(*bin, name + ".bin");
      sameValues(bin->values, name + ".bin");
    }
    if (header && (exr || bin)) {
      // Half storage: each value must be the primary's rounded to half.
      std::vector<double> v(header->values.begin(), header->values.end());
      sameValues(v, name + ".h", header->half);
    }
    if (err) {
      sameAxes(*err, name + ".err.exr");
      if (bin && !BinIsFloat64(*bin) && bin->errors.size() == err->values.size()) {
        for (size_t i = 0; i < err->values.size(); ++i)
          if (static_cast<float>(err->values[i]) != static_cast<float>(bin->errors[i])) {
            problems.push_back(name + ".err.exr differs from the error block of " + name + ".bin");
            break;
          }
      }
      double maxError = 0.0;
      for (double e : err->values) maxError = std::max(maxError, e);
      if (static_cast<float>(maxError) != static_cast<float>(t.statedErrorMax))
        problems.push_back(name + ".err.exr has max " + FormatDouble(maxError) +
                           ", the metadata says errorMax " + FormatDouble(t.statedErrorMax));
    }
    if (bin && bin->errors.size() == bin->values.size()) {
      // The error block against the .bin's own errorMax (a float64 .bin
      // states smaller bounds than the float32 files).
      double maxError = 0.0, stated = -1.0;
      for (double e : bin->errors) maxError = std::max(maxError, e);
      if (const std::string *m = bin->FindMetadata("errorMax"))
        stated = std::strtod(m->c_str(), nullptr);
      const bool wide = BinIsFloat64(*bin);
      if (wide ? maxError != stated : static_cast<float>(maxError) != static_cast<float>(stated))
        problems.push_back(name + ".bin's error block has max " + FormatDouble(maxError) +
                           ", its metadata says errorMax " + FormatDouble(stated));
    }
    if (!problems.empty()) {
      std::string detail;
      for (size_t i = 0; i < problems.size(); ++i) detail += (i ? "; " : "") + problems[i];
      Add(name, "formats", CheckStatus::kFail, detail);
    } else if (compared.empty()) {
      Add(name, "formats", CheckStatus::kSkipped, "only " + t.primary + " present");
    } else {
      std::string list;
      for (size_t i = 0; i < compared.size(); ++i) list += (i ? ", " : "") + compared[i];
      Add(name, "formats", CheckStatus::kPass,
          list + " hold the same float32 values as " + t.primary);
    }
  }

  // The KTX2, DDS and PNG files, each against the primary when it is not
  // the primary itself: the same axes, and the same values as the coarser
  // of the two storages holds them: float32 or half bit for bit (a half
  // primary, ktx2-half or dds-half alone with float files, against the
  // float values rounded to half); a b-bit PNG within half a step
  // 0.5 / (2^b - 1) plus the primary's own rounding (half an ulp: 2^-24 |p|
  // for float32, 2^-11 |p| for half), which the PNG did not see: it was
  // quantised from the double.
  void CheckTextureFormats(const Loaded &t,
                           const std::vector<std::pair<std::string, std::optional<Table>>> &files) {
    const std::string name = Name(*t.def);
    std::vector<std::string> compared, problems;
    for (const auto &[path, file] : files) {
      if (!file || path == t.primary) continue;
      const std::string what = fs::path(path).filename().string();
      if (DescribeAxis(file->x) != DescribeAxis(t.table.x) ||
          DescribeAxis(file->y) != DescribeAxis(t.table.y) ||
          DescribeAxis(file->z) != DescribeAxis(t.table.z)) {
        problems.push_back(what + " has other axes than " + t.primary);
        continue;
      }
      if (file->values.size() != t.table.values.size()) {
        problems.push_back(what + " has " + std::to_string(file->values.size()) + " values, " +
                           t.primary + " " + std::to_string(t.table.values.size()));
        continue;
      }
      const std::string storage = *file->FindMetadata("errorStorage");  // the readers require it
      const std::string *stated = t.table.FindMetadata("errorStorage");
      const bool halfPrimary = stated && *stated == "half";
      const double step = storage == "unorm8"    ? 1.0 / 255.0
                          : storage == "unorm16" ? 1.0 / 65535.0
                                                 : 0.0;
      for (size_t i = 0; i < file->values.size(); ++i) {
        const double p = t.table.values[i], a = file->values[i];
        bool same;
        if (step > 0.0)
          same = std::abs(a - p) <= 0.5 * step + std::abs(p) * (halfPrimary ? 0x1p-11 : 0x1p-24);
        else if (halfPrimary)
          same = RoundToHalf(a) == p;
        else
          same =
              static_cast<float>(a) == static_cast<float>(storage == "half" ? RoundToHalf(p) : p);
        if (!same) {
          const TexelIndex at = IndexOf(t.table, i / t.table.channels);
          problems.push_back(
              what + " differs at texel (" + std::to_string(at.x) + ", " + std::to_string(at.y) +
              (t.table.is3D() ? ", " + std::to_string(at.z) : std::string()) + ") channel " +
              std::to_string(i % t.table.channels) + ": " + FormatDouble(a) + " against " +
              FormatDouble(p) + " (" + storage + ")");
          break;
        }
      }
      if (problems.empty()) compared.push_back(what + " (" + storage + ")");
    }
    if (!problems.empty()) {
      std::string detail;
      for (size_t i = 0; i < problems.size(); ++i) detail += (i ? "; " : "") + problems[i];
      Add(name, "texture formats", CheckStatus::kFail, detail);
    } else if (!compared.empty()) {
      std::string list;
      for (size_t i = 0; i < compared.size(); ++i) list += (i ? ", " : "") + compared[i];
      Add(name, "texture formats", CheckStatus::kPass,
          list + " hold " + t.primary + "'s values as their storage rounds them");
    }
  }

  // ---- the reference ---------------------------------------------------

  BakeSettings ReferenceSettings(const Loaded &t) const {
    // The adaptive Gauss-Kronrod reference, not the bake's default panel
    // quadrature: an independent method (another parameterisation, another
    // rule, another error estimate) judges the table (unless its definition
    // names another reference, and why), far below what the table claims
    // (TableDefinition::ReferenceForCheck).
    return SettingsFor(t, t.def->ReferenceForCheck(t.statedErrorMax, options_.referenceTolerance));
  }

  // The independent rule of a table whose reference is its own
  // (CheckIndependent): what the default TableDefinition::ReferenceForCheck
  // names, ReferenceEstimator() at 1/64 of errorMax.
  BakeSettings IndependentSettings(const Loaded &t) const {
    return SettingsFor(t, t.def->TableDefinition::ReferenceForCheck(t.statedErrorMax,
                                                                    options_.referenceTolerance));
  }

  BakeSettings SettingsFor(const Loaded &t,
                           const TableDefinition::CheckReference &reference) const {
    BakeSettings s = t.model;
    s.estimator = reference.estimator;
    const double tolerance = reference.tolerance;
    // The adaptive quadrature is asked for tolerance / (2
    // kQuadratureErrorFactor) in a tolerance run, the panel rule for it.
    s.tolerance = s.estimator == Estimator::kAdaptiveQuadrature
                      ? 2.0 * kQuadratureErrorFactor * tolerance
                      : tolerance;
    return s;
  }

  // The value at a point of a table's axes (a fitted table's integrated
  // channels; its fitted ones NaN).
  PointValue Reference(const Loaded &t, double x, double y, double z) const {
    return ValueAt(t, ReferenceSettings(t), x, y, z);
  }

  // The table's integrated channels at a point of its axes under `s`.
  static PointValue ValueAt(const Loaded &t, const BakeSettings &s, double x, double y, double z) {
    return t.table.is3D() ? t.def->Evaluate3D(s, x, y, z) : t.def->EvaluateIntegrals(s, x, y);
  }

  // Every texel of every usable table, and the random points, in one
  // parallel loop (the texels cost very different amounts).
  void ComputeReferences() {
    // Task::texel of a random point and of a point of the albedo-scaling grid.
    constexpr size_t kPointTexel = SIZE_MAX, kGridTexel = SIZE_MAX - 1;
    // The panel rule's tolerance for the random points' truth (unless the
    // table's definition names one).
    constexpr double kPointTolerance = 1e-9;
    // Texels judged by the independent rule too (CheckIndependent).
    constexpr size_t kIndependentTexels = 64;
    struct Task {
      Loaded *t;
      size_t texel;  // texel index, or kPointTexel, kGridTexel
      double x, y, z;
      PointValue *out;
      // The panel rule at `tolerance` rather than the reference: the
      // furnace grid's headline numbers (see CheckAlbedoScaling, 1e-10) and
      // the random points' truth, which judge nothing.
      bool panel = false;
      double tolerance = 0.0;
      bool independent = false;  // IndependentSettings instead of the reference
    };
    std::vector<Task> tasks;
    for (auto &[kind, t] : tables_) {
      if (!t.usable) continue;
      const TableDefinition &def = *t.def;
      const size_t texels = t.table.texelCount();
      t.ref.assign(texels * t.table.channels, 0.0);
      t.refError.assign(texels * t.table.channels, 0.0);
      refTexel_[kind].resize(texels);
      for (size_t i = 0; i < texels; ++i) {
        const TexelIndex at = IndexOf(t.table, i);
        tasks.push_back({&t, i, t.table.x.TexelCenter(at.x), t.table.y.TexelCenter(at.y),
                         t.table.z.TexelCenter(at.z), &refTexel_[kind][i]});
      }
      // Where the reference is the table's own rule (the dielectric tables:
      // dielectric_table.h) and the default one, the adaptive quadrature,
      // is another, kIndependentTexels texels spread over the table by
      // that one too (CheckIndependent): an independent rule still judges
      // a sample (64 of a default glass_E's 23552 texels, 0.5 CPU-s).
      const TableDefinition::CheckReference named =
          def.ReferenceForCheck(t.statedErrorMax, options_.referenceTolerance);
      if (named.estimator != def.ReferenceEstimator() &&
          def.ReferenceEstimator() == Estimator::kAdaptiveQuadrature) {
        const size_t step = std::max<size_t>(1, texels / kIndependentTexels);
        for (size_t i = step / 2; i < texels; i += step) t.independentTexels.push_back(i);
        t.independent.resize(t.independentTexels.size());
        for (size_t k = 0; k < t.independentTexels.size(); ++k) {
          const TexelIndex at = IndexOf(t.table, t.independentTexels[k]);
          Task task{&t,
                    t.independentTexels[k],
                    t.table.x.TexelCenter(at.x),
                    t.table.y.TexelCenter(at.y),
                    t.table.z.TexelCenter(at.z),
                    &t.independent[k]};
          task.independent = true;
          tasks.push_back(task);
        }
      }
      // Random points over the whole axis ranges, edges (where lookups clamp) included.
      // Their truth judges nothing: CheckPoints holds the lookup of the
      // table to the lookup of exact texels (the texel references above),
      // and reports |lookup - truth| (interpolation included) to 3 digits.
      // For a 1D or 2D table whose reference is the adaptive quadrature the
      // truth is therefore the panel rule at kPointTolerance (3 digits of
      // any deviation above 1e-6), not the reference's nested refinement:
      // 256 such points of E_avg were 3/4 of the check of the default set.
      // A table whose definition names a tolerance for them (the dielectric
      // tables, judged by their own panel rule: dielectric_table.h) gets the
      // panel rule at that tolerance.
      const double namedTolerance =
          def.ReferenceForCheck(t.statedErrorMax, options_.referenceTolerance).pointTolerance;
      const bool panelPoints =
          namedTolerance > 0.0 ||
          (!t.table.is3D() && def.ReferenceEstimator() == Estimator::kAdaptiveQuadrature);
      const double pointTolerance = namedTolerance > 0.0 ? namedTolerance : kPointTolerance;
      RandomStream random(HashValues({options_.seed, def.SeedId()}));
      points_[kind].resize(static_cast<size_t>(options_.randomPoints));
      for (RandomPoint &p : points_[kind]) {
        p.x = t.table.x.min + (t.table.x.max - t.table.x.min) * random.NextDouble();
        p.y = t.table.is2D() ? t.table.y.min + (t.table.y.max - t.table.y.min) * random.NextDouble()
                             : 0.0;
        p.z = t.table.is3D() ? t.table.z.min + (t.table.z.max - t.table.z.min) * random.NextDouble()
                             : 0.0;
        tasks.push_back({&t, kPointTexel, p.x, p.y, p.z, &p.truth, panelPoints, pointTolerance});
      }
      // The albedo-scaling furnace's grid: cell centres of a g x g grid
      // over the axes (mu = 0 itself, infinite for Charlie's sheen, is not
      // among them).
      const std::vector<std::shared_ptr<const SetClaim>> claims = def.Claims();
      if (std::any_of(claims.begin(), claims.end(),
                      [](const auto &claim) { return claim->NeedsGrid(); })) {
        const int g = std::clamp(options_.furnaceGrid / 4, 2, 65);
        std::vector<RandomPoint> &grid = scalingGrid_[kind];
        grid.resize(static_cast<size_t>(g) * g);
        for (int j = 0; j < g; ++j)
          for (int i = 0; i < g; ++i) {
            RandomPoint &p = grid[static_cast<size_t>(j) * g + i];
            p.x = t.table.x.min + (t.table.x.max - t.table.x.min) * (i + 0.5) / g;
            p.y = t.table.y.min + (t.table.y.max - t.table.y.min) * (j + 0.5) / g;
          }
        for (RandomPoint &p : grid)
          tasks.push_back({&t, kGridTexel, p.x, p.y, 0.0, &p.truth, true, 1e-10});
      }
    }
    std::atomic<size_t> done{0};
    // Most expensive first (E_avg integrates a whole row), for balance.
    const auto cost = [](const Task &task) {
      return task.panel         ? 0.0
             : task.independent ? 16.0 * task.t->def->ReferenceCost()
                                : task.t->def->ReferenceCost();
    };
    std::stable_sort(tasks.begin(), tasks.end(),
                     [&](const Task &a, const Task &b) { return cost(a) > cost(b); });
    tbb::parallel_for(size_t{0}, tasks.size(), [&](size_t i) {
      const Task &task = tasks[i];
      try {
        if (task.panel) {
          BakeSettings s = task.t->model;
          s.estimator = Estimator::kQuadrature;
          s.tolerance = task.tolerance;
          *task.out = ValueAt(*task.t, s, task.x, task.y, task.z);
        } else if (task.independent) {
          *task.out = ValueAt(*task.t, IndependentSettings(*task.t), task.x, task.y, task.z);
        } else {
          *task.out = Reference(*task.t, task.x, task.y, task.z);
        }
      } catch (const std::domain_error &) {
        // A point where the integral is infinite (a random point drawn at
        // mu = 0 exactly for Charlie's sheen): no truth, not compared.
        task.out->value[0] = task.out->value[1] = NAN;
      }
      const size_t now = done.fetch_add(1) + 1;
      if (options_.progress && now % 64 == 0)
        options_.progress(static_cast<double>(now) / static_cast<double>(tasks.size()));
    });
    report_.referenceEvaluations = tasks.size();
    for (auto &[kind, t] : tables_) {
      if (!t.usable) continue;
      const std::vector<PointValue> &r = refTexel_[kind];
      // A fitted table's fitted channels are their own reference (CheckFit
      // judges them).
      const int fitted = t.def->FittedChannels();
      for (size_t i = 0; i < r.size(); ++i)
        for (int c = 0; c < t.table.channels; ++c) {
          const size_t at = i * t.table.channels + c;
          t.ref[at] = c < fitted ? t.table.values[at] : r[i].value[c];
          t.refError[at] = c < fitted ? 0.0 : r[i].error[c];
        }
    }
  }

  // ---- single tables ---------------------------------------------------

  void CheckFinite(const Loaded &t) {
    const std::string name = Name(*t.def);
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < t.table.values.size(); ++i)
      if (!std::isfinite(t.table.values[i]) || !std::isfinite(t.table.errors[i])) {
        if (bad++ == 0) first = i;
      }
    if (bad == 0) {
      Add(name, "finite", CheckStatus::kPass,
          std::to_string(t.table.values.size()) + " values and their bounds, no NaN or Inf");
      return;
    }
    const size_t texel = first / t.table.channels;
    const TexelIndex i = IndexOf(t.table, texel);
    const auto at = AtTexel(t.table, texel);
    Add(name, "finite", CheckStatus::kFail,
        std::to_string(bad) + " values or bounds are NaN or Inf, the first at texel (" +
            std::to_string(i.x) + ", " + std::to_string(i.y) +
            (t.table.is3D() ? ", " + std::to_string(i.z) : std::string()) + ") " + Where(at),
        static_cast<double>(bad), 0.0, at);
  }

  void CheckRange(const Loaded &t) {
    const std::string name = Name(*t.def);
    const Table &table = t.table;
    // Float rounding: a value <= 1 in double stays <= 1 in float; a sum of
    // two rounded values may exceed 1 by one ulp.
    constexpr double kSumSlack = 0x1p-23;
    const ValueClaim claim = t.def->Range(t.model);
    const std::vector<std::string> meanings = t.def->ChannelMeanings();
    double worst = 0.0;
    std::string what;
    std::vector<std::pair<std::string, double>> at;
    const size_t texels = table.texelCount();
    for (size_t i = 0; i < texels; ++i) {
      const auto note = [&](double excess, const std::string &text) {
        if (excess > worst) {
          worst = excess;
          what = text;
          at = AtTexel(table, i);
        }
      };
      for (int c = 0; c < table.channels; ++c) {
        const double v = table.values[i * table.channels + c];
        const std::string label = table.channels == 1 ? name : meanings[c];
        note(claim.lower - v, label + " < " + Short(claim.lower));
        if (std::isfinite(claim.upper)) note(v - claim.upper, label + " > " + Short(claim.upper));
        note(-table.errors[i * table.channels + c], "a negative error bound");
      }
      if (claim.sumAtMostOne) {
        double sum = 0.0;
        std::string sumLabel;
        for (int c = 0; c < table.channels; ++c) {
          sum += table.values[i * table.channels + c];
          sumLabel += (c ? " + " : "") + meanings[c];
        }
        note(sum - 1.0 - kSumSlack - 2.0 * t.storageError, sumLabel + " > 1");
      }
    }
    if (worst > 0.0) {
      Add(name, "range", CheckStatus::kFail, what + " by " + Short(worst) + " at " + Where(at),
          worst, 0.0, at);
      return;
    }
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    size_t aboveOne = 0, hiIndex = 0;
    for (size_t i = 0; i < table.values.size(); ++i) {
      const double v = table.values[i];
      lo = std::min(lo, v);
      if (v > hi) hi = v, hiIndex = i;
      aboveOne += v > 1.0 ? 1 : 0;
    }
    std::string detail = claim.text + ": values from " + Short(lo) + " to " + Short(hi);
    if (!std::isfinite(claim.upper) && aboveOne > 0) {
      const size_t texel = hiIndex / table.channels;
      detail += "; above 1 at " + std::to_string(aboveOne) + " of " +
                std::to_string(table.values.size()) + " values, the largest at " +
                Where(AtTexel(table, texel));
    }
    Add(name, "range", CheckStatus::kPass, detail);
  }

  void CheckTexels(const Loaded &t) {
    const std::string name = Name(*t.def);
    const Table &table = t.table;
    const size_t texels = table.texelCount();
    double worst = -1.0, worstAllowed = 0.0, worstReal = 0.0, realMax = 0.0, realSq = 0.0;
    size_t worstIndex = 0, realIndex = 0, outside = 0, overStated = 0;
    for (size_t i = 0; i < texels * table.channels; ++i) {
      const double real = std::abs(table.values[i] - t.ref[i]);
      const double slack =
          t.refError[i] + (t.boundsCoverStorage ? 0.0 : FloatRounding(table.values[i]));
      // The hard claim: within the stated maximum of the whole table.
      const double stated = std::max(t.statedErrorMax, t.Bound(i)) + slack;
      if (real > stated) ++overStated;
      if (real > t.Bound(i) + slack) ++outside;
      const double ratio = real / stated;
      if (ratio > worst) worst = ratio, worstIndex = i, worstAllowed = stated, worstReal = real;
      if (real > realMax) realMax = real, realIndex = i;
      realSq += real * real;
    }
    const auto where = [&](size_t i) { return AtTexel(table, i / table.channels); };
    const size_t n = texels * table.channels;
    // The per-texel bounds are 99% claims: more than 1% + 3 sigma outside fails.
    const double allowedOutside =
        std::ceil(0.01 * n + 3.0 * std::sqrt(0.01 * 0.99 * static_cast<double>(n)));
    const std::string channel =
        table.channels == 2 ? (realIndex % 2 == 0 ? " (A)" : " (B)") : std::string();
    std::string detail =
        std::to_string(n) + " values against the quadrature: max |table - truth| " +
        Short(realMax) + " at " + Where(where(realIndex)) + channel + ", rms " +
        Short(std::sqrt(realSq / n)) + "; stated errorMax " + Short(t.statedErrorMax);
    if (t.perTexelErrors)
      detail += "; " + std::to_string(outside) + " outside their own 99% bound (" +
                Short(allowedOutside) + " allowed)";
    if (overStated > 0) {
      Add(name, "texels", CheckStatus::kFail,
          std::to_string(overStated) +
              " values differ from the truth by more than the table "
              "claims; worst " +
              Short(worstReal) + " at " + Where(where(worstIndex)) + ", allowed " +
              Short(worstAllowed) + ". " + detail,
          worstReal, worstAllowed, where(worstIndex));
    } else if (t.perTexelErrors && static_cast<double>(outside) > allowedOutside) {
      Add(name, "texels", CheckStatus::kFail, "too many values outside their own bounds. " + detail,
          realMax, t.statedErrorMax, where(realIndex));
    } else {
      Add(name, "texels", CheckStatus::kPass, detail, realMax, worstAllowed, where(realIndex));
    }
  }

  // The sample of texels that the independent rule judges too, where the
  // reference is the table's own rule (ComputeReferences): each within the
  // table's stated maximum + the independent value's own bound, as
  // CheckTexels holds every texel.
  void CheckIndependent(const Loaded &t) {
    if (t.independentTexels.empty()) return;
    const Table &table = t.table;
    Worst worst;
    for (size_t k = 0; k < t.independentTexels.size(); ++k)
      for (int c = 0; c < table.channels; ++c) {
        const size_t i = t.independentTexels[k] * table.channels + c;
        const double truth = t.independent[k].value[c];
        if (!std::isfinite(truth)) continue;
        const double real = std::abs(table.values[i] - truth);
        const double allowed = std::max(t.statedErrorMax, t.Bound(i)) + t.independent[k].error[c] +
                               (t.boundsCoverStorage ? 0.0 : FloatRounding(table.values[i]));
        worst.Note(real, allowed, AtTexel(table, t.independentTexels[k]));
      }
    const std::string detail =
        std::to_string(t.independentTexels.size()) +
        " texels spread over the table also against its default reference, " +
        t.def->QuadratureDescription(IndependentSettings(t)) +
        " (every texel was judged by its own rule): max |table - truth| " + Short(worst.deviation) +
        " at " + Where(worst.at);
    if (worst.failed())
      Add(Name(*t.def), "independent", CheckStatus::kFail,
          "a value differs from the independent rule by " + Short(worst.excessDeviation) + " at " +
              Where(worst.atExcess) + ", allowed " + Short(worst.excessAllowed) + ". " + detail,
          worst.excessDeviation, worst.excessAllowed, worst.atExcess);
    else
      Add(Name(*t.def), "independent", CheckStatus::kPass, detail, worst.deviation, 0.0, worst.at);
  }

  void CheckPoints(const Loaded &t) {
    const std::string name = Name(*t.def);
    const Table &table = t.table;
    double worstLookup = 0.0, worstInterp = 0.0, worstExcess = -1.0, excessAllowed = 0.0,
           excessValue = 0.0;
    std::vector<std::pair<std::string, double>> atLookup, atExcess;
    for (const RandomPoint &p : points_.at(t.index))
      for (int c = 0; c < table.channels; ++c) {
        if (!std::isfinite(p.truth.value[c])) continue;
        const double lookup = LookupAt(table, table.values, p.x, p.y, p.z, c);
        const double lookupRef = LookupAt(table, t.ref, p.x, p.y, p.z, c);
        const double truth = p.truth.value[c];
        const double real = std::abs(lookup - truth);
        if (real > worstLookup) {
          worstLookup = real;
          worstInterp = std::abs(lookupRef - truth);
          atLookup = At(table, p.x, p.y, p.z);
        }
        // The lookups of the table and of exact texel values differ by the
        // texels' errors, weighted as the lookup weights them (weights sum
        // to 1): at most the stated errorMax.
        const double allowed = t.statedErrorMax + LookupAt(table, t.refError, p.x, p.y, p.z, c) +
                               2.0 * FloatRounding(lookup);
        const double excess = std::abs(lookup - lookupRef) - allowed;
        if (excess > worstExcess) {
          worstExcess = excess;
          excessAllowed = allowed;
          excessValue = std::abs(lookup - lookupRef);
          atExcess = At(table, p.x, p.y, p.z);
        }
      }
    const std::string detail = std::to_string(points_.at(t.index).size()) + " random points, " +
                               (table.is3D() ? "trilinear" : "bilinear") +
                               " lookup against the quadrature at the point: max |lookup - "
                               "truth| " +
                               Short(worstLookup) + " at " + Where(atLookup) +
                               ", of which interpolation of exact texels " + Short(worstInterp);
    if (worstExcess > 0.0)
      Add(name, "points", CheckStatus::kFail,
          "the lookup departs from a lookup of exact texels by " + Short(excessValue) + " at " +
              Where(atExcess) + ", allowed " + Short(excessAllowed) + ". " + detail,
          excessValue, excessAllowed, atExcess);
    else
      Add(name, "points", CheckStatus::kPass, detail, worstLookup, 0.0, atLookup);
  }

  void CheckMonotonic(const Loaded &t) {
    const std::string name = Name(*t.def);
    const Table &table = t.table;
    const std::optional<MonotonicClaim> claimed = t.def->Monotonic(t.model);
    if (!claimed) return;
    if (claimed->direction == 0) {
      Add(name, "monotonic", CheckStatus::kSkipped, claimed->skipped);
      return;
    }
    const int direction = claimed->direction;  // +1 non-decreasing, -1 non-increasing along x
    const double from = claimed->from;
    const std::string &claim = claimed->claim;
    double worst = 0.0, worstAllowed = 0.0, worstExcess = 0.0;
    std::vector<std::pair<std::string, double>> at;
    int pairs = 0;
    for (int z = 0; z < table.depth(); ++z)
      for (int y = 0; y < table.height(); ++y)
        for (int x = 0; x + 1 < table.width(); ++x) {
          if (table.x.TexelCenter(x) < from) continue;
          const size_t a = table.index(x, y, z, 0), b = table.index(x + 1, y, z, 0);
          // A step against the claimed direction, beyond what the two
          // texels' bounds allow, violates it.
          const double against = direction * (table.values[a] - table.values[b]);
          const double allowed = t.Bound(a) + t.Bound(b) + FloatRounding(table.values[a]) +
                                 FloatRounding(table.values[b]);
          ++pairs;
          if (against - allowed > worstExcess) {
            worstExcess = against - allowed;
            worst = against;
            worstAllowed = allowed;
            at = At(table, table.x.TexelCenter(x), table.y.TexelCenter(y), table.z.TexelCenter(z));
          }
        }
    if (worstExcess > 0.0)
      Add(name, "monotonic", CheckStatus::kFail,
          claim + " is violated by " + Short(worst) + " between neighbours at " + Where(at) +
              " (their bounds allow " + Short(worstAllowed) + ")",
          worst, worstAllowed, at);
    else
      Add(name, "monotonic", CheckStatus::kPass,
          claim + ": all " + std::to_string(pairs) + " neighbour pairs within their bounds");
  }

  void CheckClosedForm(const Loaded &t) {
    const std::optional<ClosedForm> closed = t.def->Closed(t.model);
    if (!closed || t.table.is3D()) return;  // closed forms are of 1D and 2D tables
    double worst = 0.0;
    std::vector<std::pair<std::string, double>> at;
    for (int y = 0; y < t.table.height(); ++y)
      for (int x = 0; x < t.table.width(); ++x) {
        const double px = t.table.x.TexelCenter(x), py = t.table.y.TexelCenter(y);
        const double exact = closed->value(px, py);
        const double excess = std::abs(t.table.values[t.table.index(x, y, 0)] - exact) -
                              FloatRounding(exact) - t.StorageRounding(exact) - 1e-15;
        if (excess > worst) worst = excess, at = At(t.table, px, py);
      }
    if (worst > 0.0)
      Add(Name(*t.def), "closed form", CheckStatus::kFail,
          closed->subject + " departs from " + closed->formula + " by " + Short(worst) +
              " beyond float rounding at " + Where(at),
          worst, 0.0, at);
    else
      Add(Name(*t.def), "closed form", CheckStatus::kPass,
          closed->subject + " = " + closed->formula + " at every texel, to float rounding");
  }

  // The closed form a slice of the table takes (the dielectric tables at
  // eta = 1), texel by texel within the texel's own claim.
  void CheckSliceClosedForm(const Loaded &t) {
    const std::optional<SliceClosedForm> closed = t.def->SliceClosed(t.model);
    if (!closed || !t.usable) return;
    const Table &table = t.table;
    const Axis &axis = closed->axis == 1 ? table.y : table.z;
    const int count = closed->axis == 1 ? table.height() : table.depth();
    int slice = -1;
    for (int k = 0; k < count; ++k)
      if (axis.TexelCenter(k) == closed->at) slice = k;
    const std::string name = Name(*t.def);
    if (slice < 0) {
      Add(name, "slice", CheckStatus::kSkipped,
          closed->subject + " = " + closed->formula + ": the table has no slice at " + axis.name +
              " = " + Short(closed->at));
      return;
    }
    Worst worst;
    int texels = 0;
    const int height = closed->axis == 1 ? 1 : table.height();
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < table.width(); ++x) {
        const int iy = closed->axis == 1 ? slice : y, iz = closed->axis == 1 ? 0 : slice;
        const size_t i = table.index(x, iy, iz, 0);
        const double a = table.x.TexelCenter(x),
                     b = closed->axis == 1 ? 0.0 : table.y.TexelCenter(y);
        const double exact = closed->value(a, b);
        const double dev = std::abs(table.values[i] - exact);
        // The hard claim of the texel (CheckTexels), the closed form's own
        // integration (1e-13 for an average) and rounding.
        const double allowed = std::max(t.statedErrorMax, t.Bound(i)) + 1e-12 +
                               (t.boundsCoverStorage ? 0.0 : FloatRounding(exact));
        const auto where =
            At(table, table.x.TexelCenter(x), table.y.TexelCenter(iy), table.z.TexelCenter(iz));
        ++texels;
        worst.Note(dev, allowed, where);
      }
    if (worst.failed())
      Add(name, "slice", CheckStatus::kFail,
          closed->subject + " departs from " + closed->formula + " by " +
              Short(worst.excessDeviation) + " at " + Where(worst.atExcess) +
              ", more than the texel's bound " + Short(worst.excessAllowed),
          worst.excessDeviation, worst.excessAllowed, worst.atExcess);
    else
      Add(name, "slice", CheckStatus::kPass,
          closed->subject + " = " + closed->formula + " at all " + std::to_string(texels) +
              " texels of the slice, within their bounds: max |table - closed form| " +
              Short(worst.deviation) + " at " + Where(worst.at),
          worst.deviation, 0.0, worst.at);
  }

  // The limits the definition's integrator reaches where the table has no
  // texel (the smooth interface): the panel rule at the claim's coordinate,
  // at the texel centres of the other axes.
  void CheckLimits(const Loaded &t) {
    if (!t.usable) return;
    const Table &table = t.table;
    for (const LimitClaim &claim : t.def->Limits(t.model)) {
      BakeSettings s = t.model;
      s.estimator = Estimator::kQuadrature;
      s.tolerance = 1e-9;
      // The two other axes, in order.
      const Axis &a = claim.axis == 0 ? table.y : table.x;
      const Axis &b = claim.axis == 2 ? table.y : table.z;
      struct Item {
        double a, b;
        PointValue v;
      };
      std::vector<Item> items;
      size_t left = 0;
      for (int j = 0; j < b.count; ++j)
        for (int i = 0; i < a.count; ++i) {
          const double va = a.TexelCenter(i), vb = b.TexelCenter(j);
          if (claim.excluded && claim.excluded(va, vb)) {
            ++left;
            continue;
          }
          items.push_back({va, vb, {}});
        }
      tbb::parallel_for(size_t{0}, items.size(), [&](size_t k) {
        Item &it = items[k];
        double c[3] = {it.a, it.b, 0.0};
        // Put the limit's coordinate in its place.
        double p[3];
        for (int n = 0, m = 0; n < 3; ++n) p[n] = n == claim.axis ? claim.near : c[m++];
        it.v = t.def->Evaluate3D(s, p[0], p[1], p[2]);
      });
      Worst worst;
      for (const Item &it : items) {
        const double exact = claim.value(it.a, it.b);
        const double dev = std::abs(it.v.value[0] - exact);
        const double allowed = it.v.error[0] + claim.slack;
        double p[3], c[2] = {it.a, it.b};
        for (int n = 0, m = 0; n < 3; ++n) p[n] = n == claim.axis ? claim.near : c[m++];
        worst.Note(dev, allowed, At(table, p[0], p[1], p[2]));
      }
      const std::string detail =
          "the integrator at " +
          (claim.axis == 0   ? table.x
           : claim.axis == 1 ? table.y
                             : table.z)
              .name +
          " = " + Short(claim.near) + " on " + std::to_string(items.size()) +
          " texel centres of the other axes" +
          (left ? " (" + std::to_string(left) + " beside a branch point left out)"
                : std::string()) +
          ": max |value - limit| " + Short(worst.deviation) + " at " + Where(worst.at) +
          "; allowed its bound + " + claim.slackText;
      if (worst.failed())
        Add(Name(*t.def), "limit", CheckStatus::kFail,
            claim.subject + " is " + claim.formula + ", but " + detail + "; off by " +
                Short(worst.excessDeviation) + " at " + Where(worst.atExcess),
            worst.excessDeviation, worst.excessAllowed, worst.atExcess);
      else
        Add(Name(*t.def), "limit", CheckStatus::kPass,
            claim.subject + " = " + claim.formula + ": " + detail, worst.deviation, 0.0, worst.at);
    }
  }

  // A fitted table (ltc_ggx): every texel usable (det M^-1 > 0); the
  // measures of the fit (lobe error, ...) recomputed for the stored texels
  // and held to what T.fit.exr states texel by texel (the same computation
  // on the same float32 values: equal to float32 rounding) and to the
  // metadata's maxima (fitErrors); and no jump between neighbours. Two
  // neighbours on different branches of the fit (a mirrored or collapsed
  // solution) interpolate, in a renderer's bilinear lookup, to a matrix that
  // fits neither; in the fit's parameters (FitParameters) they are a step
  // far larger than the steps beside it. At a line's end, where there is
  // no step two texels after, the two steps before it also stand continued
  // as a geometric sequence (step[i-1]^2 / step[i-2]): the fit changes
  // fastest toward mu = 1 (ltc_sheen at small roughness: an honest ratio of
  // 10.0 on the last step without this, 3.3 with it; refitted from its
  // neighbour's matrix the texel is the same fit). Measured on ltc_ggx: the
  // largest ratio of an honest table is 4.84 (64 x 64; 3.76 at 16 x 16,
  // grazing views), a texel swapped for its mirrored branch 23 to 88
  // (measured with a floor of 0.02); on ltc_sheen (64 x 64, both
  // visibilities and mappings) at most 4.82, a mirrored texel 15.5 and
  // more. A texel with no parameters (FitParameters empty: ltc_sheen's
  // texels that carry no light) takes part in no step.
  static constexpr double kJumpRatio = 10.0;
  static constexpr double kJumpFloor = 0.03;
  void CheckFit(const Loaded &t) {
    const std::string name = Name(*t.def);
    const Table &table = t.table;
    const int ch = table.channels;
    const size_t texels = table.texelCount();
    size_t bad = 0;
    std::string firstProblem;
    std::vector<std::pair<std::string, double>> badAt;
    for (size_t i = 0; i < texels; ++i)
      if (const std::string p = t.def->TexelProblem(&table.values[i * ch]); !p.empty()) {
        if (bad++ == 0) firstProblem = p, badAt = AtTexel(table, i);
      }
    if (bad > 0)
      Add(name, "fit usable", CheckStatus::kFail,
          std::to_string(bad) + " texels unusable, the first at " + Where(badAt) + ": " +
              firstProblem,
          static_cast<double>(bad), 0.0, badAt);
    else
      Add(name, "fit usable", CheckStatus::kPass,
          "all " + std::to_string(texels) + " texels (for ltc_ggx: det M^-1 > 0)");
    // The measures at every stored texel.
    std::vector<std::vector<std::pair<std::string, double>>> measured(texels);
    const auto valuesAt = [&](size_t i) {
      PointValue v;
      for (int c = 0; c < ch && c < kMaxTableChannels; ++c) v.value[c] = table.values[i * ch + c];
      return v;
    };
    tbb::parallel_for(size_t{0}, texels, [&](size_t i) {
      const TexelIndex k = IndexOf(table, i);
      measured[i] = t.def->PointFitErrors(t.model, table.x.TexelCenter(k.x),
                                          table.y.TexelCenter(k.y), valuesAt(i));
    });
    const std::vector<std::string> names = t.def->FitMapNames();
    std::optional<Table> map;
    const std::string mapPath = (fs::path(dir_) / (name + ".fit.exr")).string();
    std::error_code ec;
    if (fs::exists(mapPath, ec)) {
      try {
        map = ReadExrTable(mapPath);
        report_.files.push_back(mapPath);
        if (map->channelNames != names || map->values.size() != texels * names.size())
          throw IoError(mapPath + ": not the fit maps of " + name);
      } catch (const IoError &e) {
        Add(name, "fit maps", CheckStatus::kFail, e.what());
        map.reset();
      }
    }
    // The metadata's maxima: "lobeError mean 0.1 max 0.6; polygonError ...".
    const std::string *summary = table.FindMetadata("fitErrors");
    std::string detail;
    Worst worst;
    for (size_t k = 0; k < names.size(); ++k) {
      double mean = 0.0, highest = 0.0;
      for (size_t i = 0; i < texels; ++i) {
        const double v = measured[i].size() > k ? measured[i][k].second : NAN;
        mean += v / static_cast<double>(texels);
        highest = std::max(highest, v);
        // The map holds v as float32; recomputed from the same float32
        // texels it is the same double. Half storage moves the texels: no
        // texel-by-texel claim then.
        if (map && !t.halfStorage) {
          const double stated = map->values[i * names.size() + k];
          worst.Note(std::abs(v - stated), FloatRounding(v) + 1e-12, AtTexel(table, i));
        }
        if (!std::isfinite(v)) worst.Note(HUGE_VAL, 0.0, AtTexel(table, i));
      }
      // The summary prints 6 digits.
      const size_t at = summary ? summary->find(names[k] + " mean ") : std::string::npos;
      if (at != std::string::npos) {
        const size_t m = summary->find(" max ", at);
        const double stated =
            m == std::string::npos ? NAN : std::strtod(summary->c_str() + m + 5, nullptr);
        if (!(highest <= stated * (1.0 + 1e-5) + 1e-12))
          worst.Note(highest - stated, 0.0, {{names[k] + " max", highest}});
      }
      detail += (k ? "; " : "") + names[k] + " mean " + Short(mean) + " max " + Short(highest);
    }
    const std::string against = std::string(map ? name + ".fit.exr texel by texel and " : "") +
                                (summary ? "the metadata's maxima" : "nothing stated");
    if (worst.failed())
      Add(name, "fit errors", CheckStatus::kFail,
          "recomputed for the stored texels, the fit's measures depart from " + against + " by " +
              Short(worst.excessDeviation) + " at " + Where(worst.atExcess) + ". " + detail,
          worst.excessDeviation, worst.excessAllowed, worst.atExcess);
    else
      Add(name, "fit errors", summary || map ? CheckStatus::kPass : CheckStatus::kFail,
          "recomputed for the " + std::to_string(texels) + " stored texels, as " + against +
              " state: " + detail);
    // Jumps: along every row and column, the step between neighbours in the
    // fit's parameters (max over them) against the steps two texels before
    // and after it (not the adjacent ones, which a single outlier texel
    // shares).
    Worst jump;
    size_t steps = 0;
    const auto parameters = [&](int x, int y) {
      return t.def->FitParameters(&table.values[table.index(x, y, 0)]);
    };
    for (int axis = 0; axis < 2; ++axis) {
      const int along = axis == 0 ? table.width() : table.height();
      const int across = axis == 0 ? table.height() : table.width();
      for (int line = 0; line < across; ++line) {
        std::vector<std::vector<double>> p;
        for (int i = 0; i < along; ++i)
          p.push_back(axis == 0 ? parameters(i, line) : parameters(line, i));
        std::vector<double> step(along > 0 ? along - 1 : 0, 0.0);
        for (int i = 0; i + 1 < along; ++i)
          for (size_t k = 0; k < p[i].size() && k < p[i + 1].size(); ++k)
            step[i] = std::max(step[i], std::abs(p[i + 1][k] - p[i][k]));
        for (int i = 0; i + 1 < along; ++i) {
          double beside = kJumpFloor;
          for (int j : {i - 2, i + 2})
            if (j >= 0 && j + 1 < along) beside = std::max(beside, step[j]);
          if (i + 3 >= along && i >= 2 && step[i - 2] > 0.0)
            beside = std::max(beside, step[i - 1] * step[i - 1] / step[i - 2]);
          if (i < 2 && i + 3 < along && step[i + 2] > 0.0)
            beside = std::max(beside, step[i + 1] * step[i + 1] / step[i + 2]);
          const int x = axis == 0 ? i : line, y = axis == 0 ? line : i;
          const double x2 = axis == 0 ? table.x.TexelCenter(x + 1) : table.x.TexelCenter(x);
          const double y2 = axis == 0 ? table.y.TexelCenter(y) : table.y.TexelCenter(y + 1);
          jump.Note(
              step[i] / beside, kJumpRatio,
              At(table, 0.5 * (table.x.TexelCenter(x) + x2), 0.5 * (table.y.TexelCenter(y) + y2)));
          ++steps;
        }
      }
    }
    if (steps == 0) return;
    const std::string jumpDetail =
        std::to_string(steps) +
        " neighbour steps in the fit's parameters, each against the steps two texels before "
        "and after it (at least " +
        Short(kJumpFloor) + "): the largest ratio " + Short(jump.deviation) + " at " +
        Where(jump.at) + ", allowed " + Short(kJumpRatio);
    if (jump.failed())
      Add(name, "no jumps", CheckStatus::kFail,
          "neighbours on different branches of the fit: " + jumpDetail, jump.excessDeviation,
          kJumpRatio, jump.atExcess);
    else
      Add(name, "no jumps", CheckStatus::kPass, jumpDetail, jump.deviation, kJumpRatio, jump.at);
  }

  using RandomPoint = ReferencePoint;

  std::string Name(const TableDefinition &def) const { return def.Name() + suffix_; }

  std::string dir_;
  CheckOptions options_;
  std::string suffix_;
  CheckReport report_;
  // Keyed by the index in AllTables(), so that the checks run in its order.
  std::map<size_t, Loaded> tables_;
  std::map<size_t, std::vector<PointValue>> refTexel_;
  std::map<size_t, std::vector<RandomPoint>> points_;
  std::map<size_t, std::vector<RandomPoint>> scalingGrid_;
};

}  // namespace

CheckReport CheckBakedSet(const std::string &dir, const CheckOptions &options) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw IoError(dir + " is not a directory");
  // A bake plan may write variants (E_beckmann, Favg_dielectric, ...): each
  // suffix is checked as a set of its own.
  // Names longest first, so that "Eavg_x" is Eavg with suffix "_x", not E.
  std::vector<std::string> names;
  for (const TableDefinition *table : AllTables()) names.push_back(table->Name());
  std::sort(names.begin(), names.end(),
            [](const std::string &a, const std::string &b) { return a.size() > b.size(); });
  std::string alternatives;
  for (const std::string &n : names) alternatives += (alternatives.empty() ? "" : "|") + n;
  const std::regex kTableFile(
      "^(" + alternatives +
      R"()(_[A-Za-z0-9_]+)?(\.err)?\.(exr|bin|h|png|ktx2|dds|inc|js|ts|glsl|hlsl|wgsl|metal)$)");
  std::set<std::string> suffixes;
  std::set<std::string> fits;  // T_fit.h of --format fit (fit_check.h)
  for (const auto &entry : fs::directory_iterator(dir, ec)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (file.size() > 6 && file.compare(file.size() - 6, 6, "_fit.h") == 0) {
      fits.insert(entry.path().string());
      continue;
    }
    if (file.find("_fit.") != std::string::npos) continue;  // a fit's shader functions
    if (std::regex_match(file, m, kTableFile)) suffixes.insert(m[2].str());
  }
  if (suffixes.empty() && fits.empty()) suffixes.insert("");
  CheckReport report;
  for (const std::string &path : fits) {
    const auto start = std::chrono::steady_clock::now();
    report.dir = dir;
    report.files.push_back(path);
    for (CheckResult &r : CheckFitFile(path, options, &report.referenceEvaluations))
      report.results.push_back(std::move(r));
    report.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  for (const std::string &suffix : suffixes) {
    const CheckReport part = Checker(dir, options, suffix).Run();
    report.dir = part.dir;
    report.files.insert(report.files.end(), part.files.begin(), part.files.end());
    report.results.insert(report.results.end(), part.results.begin(), part.results.end());
    report.referenceEvaluations += part.referenceEvaluations;
    report.seconds += part.seconds;
  }
  return report;
}

}  // namespace lutbake
