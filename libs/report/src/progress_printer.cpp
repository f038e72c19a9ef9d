#include "tagmap/report/progress_printer.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>

namespace tagmap::report
{
namespace
{
// 1234567 -> "1,234,567": counts of points are read at a glance.
std::string groupDigits(size_t v)
{
	std::string s = std::to_string(v);
	for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<size_t>(i), ",");
	return s;
}

std::string countText(size_t done, size_t total)
{
	if (total <= 1) return done > total ? groupDigits(done) : std::string();
	return done == total ? groupDigits(done) : groupDigits(done) + "/" + groupDigits(total);
}

ProgressParams::Style resolveStyle(const ProgressParams& p)
{
	if (p.style != ProgressParams::Style::Auto) return p.style;
	const bool tty = p.stream && ::isatty(::fileno(p.stream));
	return tty ? ProgressParams::Style::Bar : ProgressParams::Style::Lines;
}
}  // namespace

ProgressParams ProgressParams::unlessQuiet(bool quiet)
{
	ProgressParams p;
	if (quiet) p.style = Style::Quiet;
	return p;
}

ProgressPrinter::ProgressPrinter(ProgressParams p) : p_(p), style_(resolveStyle(p))
{
	start_ = now();
	if (style_ == ProgressParams::Style::Quiet || !p_.stream) return;
	ticker_ = std::thread([this] { tick(); });
}

ProgressPrinter::~ProgressPrinter()
{
	{
		std::lock_guard<std::mutex> lock(mutex_);
		stopping_ = true;
	}
	wake_.notify_all();
	if (ticker_.joinable()) ticker_.join();
	// Still running here means an error is on its way: keep the bar as it
	// was (where it stopped is useful), but never claim the stage is done.
	if (!stage_.empty() && style_ == ProgressParams::Style::Bar) std::fputc('\n', p_.stream);
}

double ProgressPrinter::now() const
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::function<void(const std::string&, size_t, size_t)> ProgressPrinter::callback()
{
	return [this](const std::string& stage, size_t done, size_t total) { update(stage, done, total); };
}

void ProgressPrinter::update(const std::string& stage, size_t done, size_t total)
{
	if (style_ == ProgressParams::Style::Quiet || !p_.stream) return;
	std::lock_guard<std::mutex> lock(mutex_);
	if (stage != stage_)
	{
		endStage();
		stage_ = stage;
		stageStart_ = lastLine_ = now();
		lastDraw_ = 0;  // a new stage is drawn at once
	}
	done_ = done;
	total_ = total;
	if (total > 0 && done >= total)
		endStage();
	else if (style_ == ProgressParams::Style::Bar && now() - lastDraw_ >= p_.redrawSeconds)
		draw(false);  // stages that report per block of points call this thousands of times a second
}

void ProgressPrinter::finish()
{
	if (style_ == ProgressParams::Style::Quiet || !p_.stream) return;
	std::lock_guard<std::mutex> lock(mutex_);
	endStage();
}

void ProgressPrinter::endStage()
{
	if (stage_.empty()) return;
	draw(true);
	stage_.clear();
}

void ProgressPrinter::tick()
{
	// Lines are checked twice per interval, so none is late by more than half.
	const double period =
		style_ == ProgressParams::Style::Bar ? p_.redrawSeconds : std::max(0.05, p_.lineIntervalSeconds / 2);
	std::unique_lock<std::mutex> lock(mutex_);
	while (!stopping_)
	{
		wake_.wait_for(lock, std::chrono::duration<double>(period));
		if (stopping_ || stage_.empty()) continue;
		if (style_ == ProgressParams::Style::Bar)
		{
			spin_++;
			draw(false);
		}
		else if (now() - lastLine_ >= p_.lineIntervalSeconds)
			draw(false);
	}
}

void ProgressPrinter::draw(bool final)
{
	const double t = now();
	const double stageSeconds = t - stageStart_, totalSeconds = t - start_;
	const std::string count = countText(done_, total_);
	if (style_ == ProgressParams::Style::Lines)
	{
		std::string pct;
		if (total_ > 1 && !final) pct = " (" + std::to_string(100 * done_ / total_) + "%)";
		std::fprintf(p_.stream, "tagmap: [%7.1f s] %-20s %s%s%s\n", totalSeconds, stage_.c_str(),
					 final ? "done " : "", count.c_str(), pct.c_str());
		lastLine_ = t;
		std::fflush(p_.stream);
		return;
	}
	lastDraw_ = t;
	// Bar: "\r" + clear-to-end-of-line redraws in place; a finished stage
	// keeps its line, so the terminal ends with one line per stage.
	std::string bar;
	if (final)
		bar = "done";
	else if (total_ > 1)
	{
		const int w = p_.barWidth;
		const int filled = static_cast<int>(static_cast<double>(w) * static_cast<double>(std::min(done_, total_)) /
											static_cast<double>(total_));
		bar = "[" + std::string(static_cast<size_t>(filled), '=') + (filled < w ? ">" : "") +
			  std::string(static_cast<size_t>(std::max(0, w - filled - 1)), '.') + "] " +
			  std::to_string(100 * done_ / total_) + "%";
	}
	else
		bar = std::string("[") + "|/-\\"[spin_ % 4] + "]";
	std::fprintf(p_.stream, "\r\033[K  %-20s %-36s %-19s %6.1f s  (total %.1f s)%s", stage_.c_str(), bar.c_str(),
				 count.c_str(), stageSeconds, totalSeconds, final ? "\n" : "");
	std::fflush(p_.stream);
}

}  // namespace tagmap::report
