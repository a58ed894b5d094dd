#include "campaign_progress.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace rsi {

CampaignProgress::CampaignProgress(int n_runs, bool terminal)
    : m_fraction(static_cast<size_t>(n_runs), 0.0)
    , m_start(Clock::now())
    , m_terminal(terminal) {}

double CampaignProgress::elapsed() const {
  return std::chrono::duration<double>(Clock::now() - m_start).count();
}

double CampaignProgress::fraction_done() const {
  return std::accumulate(m_fraction.begin(), m_fraction.end(), 0.0) /
         static_cast<double>(m_fraction.size());
}

std::string CampaignProgress::counts() const {
  const std::lock_guard<std::mutex> lock(m_mutex);
  return counts_locked();
}

std::string CampaignProgress::counts_locked() const {
  const double seconds = elapsed();
  const double f = fraction_done();
  char text[160];
  if (m_done == static_cast<int>(m_fraction.size()) || !(f > 0.0))
    std::snprintf(text, sizeof text, "[%d/%zu runs, %.1f s elapsed]", m_done, m_fraction.size(),
                  seconds);
  else
    std::snprintf(text, sizeof text, "[%d/%zu runs, %.1f s elapsed, about %.0f s left]", m_done,
                  m_fraction.size(), seconds, seconds * (1.0 - f) / f);
  return text;
}

void CampaignProgress::update(int run, double fraction) {
  const std::lock_guard<std::mutex> lock(m_mutex);
  m_fraction[static_cast<size_t>(run)] = std::min(std::max(fraction, 0.0), 1.0);
  if (!m_terminal) return;
  const double seconds = elapsed();
  if (seconds <= 1.0 || (m_drawn && seconds - m_last_drawn < 0.25)) return;
  const double f = fraction_done();
  std::fprintf(stderr, "\r\033[Kcampaign: %d/%zu runs done, %5.1f%% (%.1f s, about %.0f s left)",
               m_done, m_fraction.size(), 100.0 * f, seconds,
               f > 0.0 ? seconds * (1.0 - f) / f : 0.0);
  std::fflush(stderr);
  m_drawn = true;
  m_last_drawn = seconds;
}

void CampaignProgress::finished(int run, const std::string& name, const std::string& outcome) {
  const std::lock_guard<std::mutex> lock(m_mutex);
  m_fraction[static_cast<size_t>(run)] = 1.0;
  ++m_done;
  const std::string line = counts_locked();
  // The live line, if drawn, is replaced by this one (and redrawn by the next update).
  std::fprintf(stderr, "%s%-10s %s   %s\n", m_drawn ? "\r\033[K" : "", name.c_str(),
               outcome.c_str(), line.c_str());
  m_drawn = false;
}

} // namespace rsi
