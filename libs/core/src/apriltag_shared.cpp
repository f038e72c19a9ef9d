// Decode tables shared by every detector of the process: libapriltag keeps
// a family's quick-decode hash table inside the family object (hundreds of
// MB for the large families), and reads it only while detecting, so one
// copy serves all decoder threads.
//
// The table is built here rather than by apriltag_detector_add_family_bits:
// libapriltag sizes it for twice the 2-bit entries there are and then
// three times that (load 1/6), 590 MB for all eight families; at load 1/2
// the same entries take 320 MB, and a lookup probes ~2.5 slots, not ~1.2.
// Lookups find the same entries, so decodes are unchanged. The layout is
// libapriltag 3's (apriltag.c: struct quick_decode / quick_decode_entry),
// freed by its own quick_decode_uninit with free().
#include <apriltag/apriltag.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <utility>

#include "tagmap/apriltag_families.h"

namespace tagmap
{
namespace
{
struct QuickDecodeEntry  // libapriltag 3: struct quick_decode_entry
{
	uint64_t rcode;
	uint16_t id;
	uint8_t hamming;
	uint8_t rotation;
};
struct QuickDecode  // libapriltag 3: struct quick_decode
{
	int nentries;
	QuickDecodeEntry* entries;
};

// libapriltag's quick_decode_init, with the table sized for the entries it
// really adds (codes, then 1-bit and 2-bit flips) at load 1/2.
bool buildQuickDecode(apriltag_family_t* fam, int maxHamming)
{
	const uint64_t codes = fam->ncodes, bits = fam->nbits;
	if (maxHamming > 2 || bits >= 64) return false;
	uint64_t entries = codes;
	if (maxHamming >= 1) entries += codes * bits;
	if (maxHamming >= 2) entries += codes * bits * (bits - 1) / 2;
	const uint64_t slots = 2 * entries + 1;
	if (slots > 0x7fffffff) return false;
	auto* qd = static_cast<QuickDecode*>(std::calloc(1, sizeof(QuickDecode)));
	auto* table = static_cast<QuickDecodeEntry*>(std::malloc(slots * sizeof(QuickDecodeEntry)));
	if (!qd || !table)
	{
		std::free(qd);
		std::free(table);
		return false;
	}
	for (uint64_t i = 0; i < slots; i++) table[i] = {UINT64_MAX, 0, 0, 0};
	qd->nentries = static_cast<int>(slots);
	qd->entries = table;
	auto add = [&](uint64_t code, uint32_t id, int hamming) {
		uint32_t bucket = static_cast<uint32_t>(code % slots);
		while (table[bucket].rcode != UINT64_MAX) bucket = static_cast<uint32_t>((bucket + 1) % slots);
		table[bucket].rcode = code;
		table[bucket].id = static_cast<uint16_t>(id);
		table[bucket].hamming = static_cast<uint8_t>(hamming);
	};
	for (uint32_t i = 0; i < fam->ncodes; i++)
	{
		const uint64_t code = fam->codes[i];
		add(code, i, 0);
		if (maxHamming >= 1)
			for (uint64_t j = 0; j < bits; j++) add(code ^ (uint64_t{1} << j), i, 1);
		if (maxHamming >= 2)
			for (uint64_t j = 0; j < bits; j++)
				for (uint64_t k = 0; k < j; k++) add(code ^ (uint64_t{1} << j) ^ (uint64_t{1} << k), i, 2);
	}
	fam->impl = qd;
	return true;
}
}  // namespace

int affordableBitsCorrected(const std::string& name, int wanted)
{
	const AprilTagFamilyPtr fam = createAprilTagFamily(name);
	const uint64_t codes = fam->ncodes, bits = fam->nbits;
	int b = 0;
	uint64_t entries = codes, perCode = 1;
	for (int next = 1; next <= wanted; next++)
	{
		perCode = perCode * (bits - next + 1) / next;  // C(bits, next)
		entries += codes * perCode;
		if (entries > kDecodeTableEntryBudget) break;
		b = next;
	}
	return b;
}

std::shared_ptr<apriltag_family> sharedAprilTagFamily(const std::string& name, int bitsCorrected)
{
	static std::mutex mutex;
	static std::map<std::pair<std::string, int>, std::weak_ptr<apriltag_family>> cache;
	std::lock_guard<std::mutex> lock(mutex);
	std::weak_ptr<apriltag_family>& slot = cache[{name, bitsCorrected}];
	if (auto live = slot.lock()) return live;
	AprilTagFamilyPtr made = createAprilTagFamily(name);
	const auto destroyFamily = made.get_deleter();
	if (!buildQuickDecode(made.get(), bitsCorrected))
	{
		// Out of the compact builder's range: libapriltag's own, through a
		// throw-away detector detached before it is destroyed.
		apriltag_detector_t* builder = apriltag_detector_create();
		apriltag_detector_add_family_bits(builder, made.get(), bitsCorrected);
		zarray_clear(builder->tag_families);
		apriltag_detector_destroy(builder);
	}
	std::shared_ptr<apriltag_family> family(made.release(), [destroyFamily](apriltag_family* f) {
		apriltag_detector_t* owner = apriltag_detector_create();
		zarray_add(owner->tag_families, &f);
		apriltag_detector_destroy(owner);  // frees the tables
		destroyFamily(f);
	});
	slot = family;
	return family;
}

}  // namespace tagmap
