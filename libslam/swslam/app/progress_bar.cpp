#include <swslam/app/progress_bar.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <unistd.h>

namespace swslam::app
{
bool isTerminal(std::FILE* f) { return ::isatty(fileno(f)) == 1; }

ProgressStyle progressStyleFor(std::FILE* f, bool wanted)
{
  return !wanted ? ProgressStyle::Off : isTerminal(f) ? ProgressStyle::Bar : ProgressStyle::Lines;
}

ProgressBar::ProgressBar(std::FILE* out, bool enabled)
    : ProgressBar(out, enabled ? ProgressStyle::Bar : ProgressStyle::Off)
{
}

ProgressBar::ProgressBar(std::FILE* out, ProgressStyle style, std::string prefix)
    : out_(out), style_(style), prefix_(std::move(prefix)), start_(std::chrono::steady_clock::now()),
      last_draw_(start_)
{
}

std::string ProgressBar::format(double fraction, size_t scans, double elapsed_s, const std::string& extra)
{
  fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
  constexpr int width = 30;
  const int filled = static_cast<int>(std::lround(fraction * width));
  std::string bar(filled, '#');
  bar.append(width - filled, '.');
  const double rate = elapsed_s > 0 ? scans / elapsed_s : 0;
  char eta[32] = "--:--";
  if (fraction > 0.01 && elapsed_s > 0)
  {
    const long left = std::lround(elapsed_s * (1 - fraction) / fraction);
    std::snprintf(eta, sizeof(eta), "%ld:%02ld", left / 60, left % 60);
  }
  char buf[256];
  std::snprintf(buf, sizeof(buf), "[%s] %3.0f%% %zu scans %.0f scans/s ETA %s", bar.c_str(),
                100 * fraction, scans, rate, eta);
  return extra.empty() ? buf : std::string(buf) + " " + extra;
}

bool ProgressBar::due() const
{
  return style_ != ProgressStyle::Off &&
         (!drawn_ || std::chrono::steady_clock::now() - last_draw_ >= std::chrono::milliseconds(200));
}

void ProgressBar::update(double fraction, size_t scans, const std::string& extra)
{
  if (!due()) return;
  const auto now = std::chrono::steady_clock::now();
  last_draw_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (style_ == ProgressStyle::Lines)
  {
    const int tenths = std::isfinite(fraction) ? static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 10) : 0;
    if (tenths <= tenths_shown_) return;
    tenths_shown_ = tenths;
    const std::string text = format(fraction, scans, elapsed, extra);
    // Without the bar itself: "NN% ... ETA m:ss extra".
    std::fprintf(out_, "%s%s\n", prefix_.c_str(), text.substr(text.find(']') + 2).c_str());
  }
  else
    std::fprintf(out_, "\r%s\033[K", format(fraction, scans, elapsed, extra).c_str());
  std::fflush(out_);
}

void ProgressBar::done()
{
  if (style_ != ProgressStyle::Bar || !drawn_) return;
  std::fprintf(out_, "\r\033[K");
  std::fflush(out_);
}

}  // namespace swslam::app
