// Progress for people: a redrawn bar with counts and elapsed time when stderr
// is a terminal, plain periodic lines when it is a log file or a pipe, and
// nothing at all when quiet. Plugs into Pipeline::detect() as its ProgressFn.
//
//   tagmap::report::ProgressPrinter progress;          // style from isatty(stderr)
//   progress.update("reading", 0, 0);                    // 0 of 0: no count yet
//   map = io::loadPointCloud(path);
//   progress.update("reading", map.size(), map.size());
//   found = pipeline.detect(map, progress.callback());
//   progress.finish();
#pragma once

#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace tagmap::report
{
struct ProgressParams
{
	enum class Style
	{
		Auto,  // Bar when the stream is a terminal, else Lines
		Bar,
		Lines,
		Quiet
	};
	Style style = Style::Auto;
	std::FILE* stream = stderr;
	/** Lines: a progress line per running stage at most this often (plus one
	 *  when each stage ends), so logs stay short on long runs. */
	double lineIntervalSeconds = 2.0;
	/** Bar: redraw period; the bar also moves (spinner, elapsed time) while a
	 *  stage reports nothing, so a long read never looks hung. */
	double redrawSeconds = 0.1;
	int barWidth = 28;

	/** Auto, or Quiet for a command's --quiet. */
	static ProgressParams unlessQuiet(bool quiet);
};

class ProgressPrinter
{
   public:
	explicit ProgressPrinter(ProgressParams p = {});
	~ProgressPrinter();  // without finish(): an error; the running stage is not marked done
	ProgressPrinter(const ProgressPrinter&) = delete;
	ProgressPrinter& operator=(const ProgressPrinter&) = delete;

	/** `done` of `total` items of `stage`; total 0 (or 1 with done 0) means
	 *  "started, no count". A new stage name ends the previous stage. */
	void update(const std::string& stage, size_t done, size_t total);

	/** A callable for Pipeline::detect(); valid while this printer lives. */
	std::function<void(const std::string&, size_t, size_t)> callback();

	/** Ends the running stage and leaves the cursor on a fresh line; call
	 *  before printing anything else to the stream. */
	void finish();

	ProgressParams::Style style() const { return style_; }

   private:
	void tick();
	void endStage();  // with mutex_ held
	void draw(bool final);  // with mutex_ held
	double now() const;

	ProgressParams p_;
	ProgressParams::Style style_;
	std::mutex mutex_;
	std::condition_variable wake_;
	std::thread ticker_;
	bool stopping_ = false;

	std::string stage_;
	size_t done_ = 0, total_ = 0;
	double start_ = 0, stageStart_ = 0, lastLine_ = 0, lastDraw_ = 0;
	unsigned spin_ = 0;
};

}  // namespace tagmap::report
