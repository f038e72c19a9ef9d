// Deterministic parallel-for over an index range, with std::thread: the
// range is cut into fixed blocks, so results written per index are the same
// for any thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <memory>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace tagmap
{
/** Calls f(begin, end) on consecutive blocks of [0, n) from `threads` threads. */
template <typename F>
void parallelForBlocks(size_t n, unsigned threads, F&& f, size_t blockSize = 4096)
{
	threads = std::max(1u, threads);
	if (threads == 1 || n <= blockSize)
	{
		f(size_t{0}, n);
		return;
	}
	std::atomic<size_t> next{0};
	auto worker = [&] {
		for (size_t b; (b = next.fetch_add(blockSize)) < n;) f(b, std::min(n, b + blockSize));
	};
	std::vector<std::thread> pool;
	for (unsigned t = 1; t < threads; t++) pool.emplace_back(worker);
	worker();
	for (auto& t : pool) t.join();
}

/** Like parallelForBlocks, but f(worker, begin, end) also gets the index of
 *  the worker thread (0 .. threads-1), for per-thread scratch objects. */
template <typename F>
void parallelForWorkers(size_t n, unsigned threads, F&& f, size_t blockSize = 1)
{
	threads = std::max(1u, threads);
	std::atomic<size_t> next{0};
	auto worker = [&](unsigned w) {
		for (size_t b; (b = next.fetch_add(blockSize)) < n;) f(w, b, std::min(n, b + blockSize));
	};
	std::vector<std::thread> pool;
	for (unsigned t = 1; t < threads && t < n; t++) pool.emplace_back(worker, t);
	worker(0);
	for (auto& t : pool) t.join();
}

/** Cuts [0, n) into `chunks` contiguous, nearly equal ranges and calls
 *  f(chunk, begin, end) for each, one thread per chunk. For passes whose
 *  per-chunk partial results are combined in chunk order (histograms,
 *  prefix sums, bounds), so the combination does not depend on timing. */
template <typename F>
void parallelForChunks(size_t n, unsigned chunks, F&& f)
{
	chunks = std::max(1u, chunks);
	auto range = [&](unsigned c) { return std::make_pair(n * c / chunks, n * (c + 1) / chunks); };
	if (chunks == 1)
	{
		f(0u, size_t{0}, n);
		return;
	}
	std::vector<std::thread> pool;
	for (unsigned c = 1; c < chunks; c++)
		pool.emplace_back([&f, c, r = range(c)] { f(c, r.first, r.second); });
	const auto r0 = range(0);
	f(0u, r0.first, r0.second);
	for (auto& t : pool) t.join();
}

/** std::allocator, except that a vector's resize() leaves its new elements
 *  of a trivial type unset. For buffers a parallel loop fills right after:
 *  std::vector would zero them on one thread first, touching (faulting in)
 *  every page of hundreds of MB at the large maps' sizes; unset, each page
 *  is first touched by the worker that fills it. */
template <typename T>
struct LeftUnset : std::allocator<T>
{
	template <typename U>
	struct rebind
	{
		using other = LeftUnset<U>;
	};
	LeftUnset() = default;
	template <typename U>
	LeftUnset(const LeftUnset<U>&) noexcept
	{
	}
	template <typename U>
	void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>)
	{
		::new (static_cast<void*>(p)) U;  // default-initialised: a trivial U is left as it is
	}
	template <typename U, typename... Args>
	void construct(U* p, Args&&... args)
	{
		::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
	}
};

/** A vector whose resize() does not zero (LeftUnset): fill every element. */
template <typename T>
using FilledInParallel = std::vector<T, LeftUnset<T>>;

/** Number of threads to use: `requested`, or the hardware's when 0. */
inline unsigned resolveThreads(unsigned requested)
{
	return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace tagmap
