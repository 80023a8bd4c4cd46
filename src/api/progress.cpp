#include "lutbake/api/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace lutbake {

namespace {

constexpr int kBarWidth = 25;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ProgressPrinter::Style ProgressPrinter::StyleFor(FILE *stream, bool quiet) {
  if (quiet) return Style::kNone;
  return ::isatty(::fileno(stream)) != 0 ? Style::kBar : Style::kLines;
}

ProgressPrinter::ProgressPrinter(std::string command, Style style, FILE *stream, double lineSeconds)
    : command_(std::move(command)),
      style_(style),
      stream_(stream),
      lineSeconds_(lineSeconds),
      partStart_(std::chrono::steady_clock::now()),
      lastLine_(partStart_) {}

ProgressPrinter::~ProgressPrinter() { Clear(); }

std::string ProgressPrinter::Describe(const std::string &what, double fraction, double secondsLeft,
                                      bool bar) {
  const int percent = std::clamp(static_cast<int>(std::floor(fraction * 100.0)), 0, 100);
  std::string text = what;
  if (bar) {
    const int filled = percent * kBarWidth / 100;
    text += " [" + std::string(static_cast<size_t>(filled), '#') +
            std::string(static_cast<size_t>(kBarWidth - filled), ' ') + "]";
  }
  char number[64];
  std::snprintf(number, sizeof number, " %3d%%", percent);
  text += number;
  if (secondsLeft >= 0.0 && percent < 100) {
    std::snprintf(number, sizeof number, "  about %.0f s left", std::ceil(secondsLeft));
    text += number;
  }
  return text;
}

void ProgressPrinter::Update(const std::string &what, double fraction) {
  if (style_ == Style::kNone) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (what != what_) {
    what_ = what;
    percent_ = -1;
    partStart_ = std::chrono::steady_clock::now();
  }
  const int percent = std::clamp(static_cast<int>(std::floor(fraction * 100.0)), 0, 100);
  if (percent <= percent_) return;
  percent_ = percent;
  // The time left at the part's pace so far, once there is a pace to go by.
  const double elapsed = SecondsSince(partStart_);
  const double left = fraction > 0.02 && elapsed > 0.5 ? elapsed * (1.0 - fraction) / fraction : -1;
  Show(Describe(what, fraction, left, style_ == Style::kBar), percent >= 100);
}

void ProgressPrinter::Status(const std::string &text) {
  if (style_ == Style::kNone) return;
  std::lock_guard<std::mutex> lock(mutex_);
  Show(text, false);
}

// Called with mutex_ held.
void ProgressPrinter::Show(const std::string &text, bool finished) {
  if (style_ == Style::kBar) {
    std::fprintf(stream_, "\r\033[K%s: %s", command_.c_str(), text.c_str());
    drawn_ = true;
    if (finished) {
      std::fprintf(stream_, "\r\033[K");
      drawn_ = false;
    }
    std::fflush(stream_);
    return;
  }
  if (finished || SecondsSince(lastLine_) < lineSeconds_) return;
  lastLine_ = std::chrono::steady_clock::now();
  std::fprintf(stream_, "%s: %s\n", command_.c_str(), text.c_str());
  std::fflush(stream_);
}

void ProgressPrinter::Clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!drawn_) return;
  std::fprintf(stream_, "\r\033[K");
  std::fflush(stream_);
  drawn_ = false;
}

}  // namespace lutbake
