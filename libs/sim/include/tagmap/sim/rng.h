// Deterministic random streams. Every block of rays, every drift step and
// every random scene choice gets its own generator derived from the user's
// seed and the block's identity, so results never depend on how work is
// split between threads or in which order blocks finish.
#pragma once

#include <cstdint>
#include <cmath>
#include <random>

namespace tagmap::sim
{
/** SplitMix64 finaliser: a cheap, well-mixed hash for combining seeds. */
inline uint64_t mixSeed(uint64_t x)
{
	x += 0x9E3779B97F4A7C15ull;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
	return x ^ (x >> 31);
}

/** Seed for stream (`domain`, a, b) under the user's `seed`. */
inline uint64_t streamSeed(uint64_t seed, uint64_t domain, uint64_t a = 0, uint64_t b = 0)
{
	return mixSeed(mixSeed(mixSeed(seed ^ mixSeed(domain)) ^ a) ^ b);
}

// Stream domains (arbitrary distinct constants).
enum : uint64_t
{
	kStreamRays = 1,
	kStreamDrift = 2,
	kStreamScene = 3
};

using Rng = std::mt19937_64;

/** Standard normal sample. std::normal_distribution keeps a cached second
 *  value between calls; a fresh one per call keeps streams reproducible
 *  no matter which other draws happen in between. */
inline double gaussian(Rng& rng)
{
	// Box-Muller with one output: deterministic given the generator state.
	std::uniform_real_distribution<double> u(0.0, 1.0);
	double u1 = u(rng);
	while (u1 <= 1e-300) u1 = u(rng);
	const double u2 = u(rng);
	return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

}  // namespace tagmap::sim
