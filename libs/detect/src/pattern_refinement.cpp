#include "tagmap/pattern_refinement.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <opencv2/imgproc.hpp>

#include "tagmap/read_evidence.h"
#include "tagmap/tag_family.h"
#include "tagmap/tag_pose.h"

namespace tagmap
{
namespace
{
/** The bitmap model's resolution: 8 px per cell resolves a blur of a
 *  tenth of a cell and keeps bilinear sampling smooth within a cell. */
constexpr int kPxPerCell = 8;
/** The blur each point's own footprint puts on the pattern, as a Gaussian
 *  sigma in local point spacings. The same number as plane.splat_spacings'
 *  default, but not that parameter: splat_spacings is how the image is
 *  rendered (users raise it to fill holes in sparse maps), this is how the
 *  points sample the tag; following splat_spacings changed the results of
 *  any configuration that sets it (tested at 0.9: accuracy and presenters
 *  JSON differ). */
constexpr double kPointFootprintSpacings = 0.6;
/** Smallest blur applied to the model, in model pixels: OpenCV's kernel
 *  is a no-op below ~0.3 px, and the model must stay a smooth function. */
constexpr double kMinBlurPx = 0.3;
/** Fewer points on the tag's grid than this and a correlation (and a fit
 *  of 3-4 pose parameters with a gain and an offset) means nothing: the
 *  decoded square lies mostly off the points. */
constexpr size_t kMinPoints = 20;
/** Blurs tried besides the points' own footprint, in cells: a map merged
 *  from drifting or badly deskewed views smears a cell over about a third,
 *  or about two thirds, of its neighbour (the motion-blurred parking tags). */
constexpr double kSmearedBlurCells[] = {0.35, 0.7};
/** Levenberg-Marquardt: damping at the start, its floor, how it falls after
 *  a step that lowered the cost and grows after one that did not, and how
 *  many damped steps are tried per iteration before the fit stops (6
 *  failures raise the damping 8^6 ~ 2.6e5 times: the step is then a
 *  vanishing gradient step). */
constexpr double kInitialDamping = 1e-3, kMinDamping = 1e-6, kDampingDown = 4, kDampingUp = 8;
constexpr int kDampedTries = 6;
/** Numeric Jacobian steps: a small angle and scale change (0.002: 0.1 deg,
 *  0.2 %), a twentieth of a cell in position; well above the residuals'
 *  float noise, well below a cell. */
constexpr double kAngleStep = 0.002, kShiftStepCells = 0.05, kLogScaleStep = 0.002;

// The bitmap as a smooth function of tag-plane coordinates: upsampled and
// blurred by the point footprint, so the fit has gradients to follow.
struct PatternModel
{
	cv::Mat img;  // CV_32F, 0 (black) .. 1 (white)
	double cellsToCentre = 0;  // cells from the grid's top-left corner to the tag centre
	int cells = 0;
	int borderCells = 0;

	PatternModel(const TagBitmap& bm, double blurCells)
	{
		cells = bm.cells;
		borderCells = bm.borderCells;
		cellsToCentre = bm.centreInCells();
		cv::Mat small(bm.cells, bm.cells, CV_8U, const_cast<uint8_t*>(bm.pixels.data()));
		cv::Mat big;
		cv::resize(small, big, cv::Size(), kPxPerCell, kPxPerCell, cv::INTER_NEAREST);
		big.convertTo(img, CV_32F, 1.0 / 255);
		const double s = std::max(kMinBlurPx, blurCells * kPxPerCell);
		cv::GaussianBlur(img, img, cv::Size(), s, s, cv::BORDER_REPLICATE);
	}

	/** Value at tag-frame (x, y) in cells (x right, y up from the centre).
	 *  Beyond the grid it is the grid's edge (the white quiet zone, and the
	 *  paper around it): a point that crosses the grid's edge during the fit
	 *  then changes the cost continuously. Dropping such points instead
	 *  made the cost jump by a point's whole residual, larger than the
	 *  change a step of a few hundredths of a degree makes, and the fit
	 *  stopped at its start, up to 0.3 deg off in-plane. */
	double sample(double xc, double yc) const
	{
		const double col = std::clamp((xc + cellsToCentre) * kPxPerCell - 0.5, 0.0, img.cols - 1.000001);
		const double row = std::clamp((-yc + cellsToCentre) * kPxPerCell - 0.5, 0.0, img.rows - 1.000001);
		const int c0 = std::min(static_cast<int>(col), img.cols - 2), r0 = std::min(static_cast<int>(row), img.rows - 2);
		const double fc = col - c0, fr = row - r0;
		const float* a = img.ptr<float>(r0);
		const float* b = img.ptr<float>(r0 + 1);
		return (1 - fr) * ((1 - fc) * a[c0] + fc * a[c0 + 1]) + fr * ((1 - fc) * b[c0] + fc * b[c0 + 1]);
	}
};

/** The models with a smeared blur (kSmearedBlurCells, wider than the
 *  points' own footprint): the same for every read of a code, so they are
 *  built once per bitmap and blur rather than per read (a Gaussian of up
 *  to 47 taps over 80 x 80 pixels each; building the three models was
 *  about a third of a scan's fit). The footprint's own blur varies with
 *  each read's spacing and is not kept. Bounded: emptied when full, which
 *  changes only the time. */
class SmearedModels
{
   public:
	std::shared_ptr<const PatternModel> get(const TagBitmap& bm, double blurCells)
	{
		Key key{bm.cells, bm.borderStart, bm.borderCells, blurCells, bm.pixels};
		{
			std::lock_guard<std::mutex> lock(mutex_);
			if (const auto it = models_.find(key); it != models_.end()) return it->second;
		}
		auto model = std::make_shared<const PatternModel>(bm, blurCells);
		std::lock_guard<std::mutex> lock(mutex_);
		if (models_.size() >= kMaxModels) models_.clear();
		return models_.emplace(std::move(key), std::move(model)).first->second;
	}

   private:
	using Key = std::tuple<int, int, int, double, std::vector<uint8_t>>;
	static constexpr size_t kMaxModels = 512;  // ~25 kB each for a 10-cell grid
	std::mutex mutex_;
	std::map<Key, std::shared_ptr<const PatternModel>> models_;
};

SmearedModels& smearedModels()
{
	static SmearedModels cache;
	return cache;
}

struct FitState
{
	double theta = 0, dx = 0, dy = 0, logScale = 0;  // relative to the initial pose and size
};

// A point of the initial tag frame in the refined one, in cells: the
// inverse of (rotate by theta, then shift), over the refined cell.
struct RefinedFrame
{
	double dx, dy, c, sn, cell;
	RefinedFrame(const FitState& s, double cell0)
		: dx(s.dx), dy(s.dy), c(std::cos(s.theta)), sn(std::sin(s.theta)), cell(cell0 * std::exp(s.logScale))
	{
	}
	Eigen::Vector2d inCells(const Eigen::Vector2d& q) const
	{
		const double x = q.x() - dx, y = q.y() - dy;
		return {(c * x + sn * y) / cell, (-sn * x + c * y) / cell};
	}
};

/** Bins a third of a cell wide: the pattern's correlation is judged on the
 *  points' means over them (binnedCorrelation()). */
constexpr double kBinsPerCell = 3;

// The correlation of the points' intensities with the model, over the
// means of the points in each bin a third of a cell wide (weighted by the
// points in it). Per point, a sensor's intensity noise can outweigh the
// print's contrast (121 points per cell, per-point correlation 0.36): the
// question is whether the pattern is in the points, and means over a bin
// keep the pattern while the noise averages out; a wrong pattern stays
// wrong at any scale. With a point per bin it is the per-point correlation.
double binnedCorrelation(const std::vector<Eigen::Vector2d>& q, const std::vector<double>& I,
						 const std::vector<double>& model)
{
	if (q.empty()) return 0;
	// The points lie on the tag's grid (fitBitmap's reach): a dense array
	// of bins, x-major, spans them.
	std::vector<int64_t> bx(q.size()), by(q.size());
	for (size_t k = 0; k < q.size(); k++)
	{
		bx[k] = static_cast<int64_t>(std::floor(q[k].x() * kBinsPerCell));
		by[k] = static_cast<int64_t>(std::floor(q[k].y() * kBinsPerCell));
	}
	const auto [x0, x1] = std::minmax_element(bx.begin(), bx.end());
	const auto [y0, y1] = std::minmax_element(by.begin(), by.end());
	const int64_t minX = *x0, minY = *y0, height = *y1 - minY + 1;
	std::vector<std::array<double, 3>> bins(static_cast<size_t>((*x1 - minX + 1) * height));  // points, model sum, intensity sum
	for (size_t k = 0; k < q.size(); k++)
	{
		std::array<double, 3>& b = bins[static_cast<size_t>((bx[k] - minX) * height + (by[k] - minY))];
		b[0] += 1, b[1] += model[k], b[2] += I[k];
	}
	double n = 0, sm = 0, sI = 0, smm = 0, smI = 0, sII = 0;
	for (const std::array<double, 3>& b : bins)
	{
		if (b[0] == 0) continue;
		const double m = b[1] / b[0], v = b[2] / b[0], w = b[0];
		n += w, sm += w * m, sI += w * v, smm += w * m * m, smI += w * m * v, sII += w * v * v;
	}
	const double vm = smm / n - (sm / n) * (sm / n), vI = sII / n - (sI / n) * (sI / n);
	const double cov = smI / n - (sm / n) * (sI / n);
	return vm > 0 && vI > 0 ? cov / std::sqrt(vm * vI) : 0;
}

struct Evaluation
{
	double cost = 0;  // mean squared residual after the best affine intensity map
	double correlation = 0;
	Eigen::VectorXd residuals;
};

// How far the pattern can slide along one axis of the tag (0: x, 1: y),
// in cells, with no point's predicted colour changing: the shifts the
// points cannot tell apart. A scan's rows about a cell apart, crossing the
// cells all at the same height, leave most of a cell (32 beams at 3 m: 0.9);
// points at every height (a merged map, rows slanting across a tag seen
// obliquely) leave hundredths.
double freeShift(const std::vector<Eigen::Vector2d>& inCells, const TagBitmap& bm, int axis)
{
	constexpr double kCap = 2;  // cells: a pattern this free was not read by any decoder
	const double toCentre = bm.centreInCells();
	auto white = [&](Eigen::Vector2d at) {
		const int col = std::clamp(static_cast<int>(std::floor(at.x() + toCentre)), 0, bm.cells - 1);
		const int row = std::clamp(static_cast<int>(std::floor(-at.y() + toCentre)), 0, bm.cells - 1);
		return bm.at(row, col) != 0;
	};
	// The pattern moved by +d along the axis moves each point by -d in the
	// pattern's coordinates: the nearest colour change below a point bounds
	// the slide one way, the nearest above it the other.
	double plus = kCap, minus = kCap;
	for (const Eigen::Vector2d& p : inCells)
	{
		const bool own = white(p);
		const double v = p[axis];
		Eigen::Vector2d beyond = p;
		for (double edge = std::floor(v); v - edge < plus; edge -= 1)
		{
			beyond[axis] = edge - 0.5;
			if (white(beyond) != own) plus = v - edge;
		}
		for (double edge = std::floor(v) + 1; edge - v < minus; edge += 1)
		{
			beyond[axis] = edge + 0.5;
			if (white(beyond) != own) minus = edge - v;
		}
	}
	return std::min(plus + minus, kCap);
}

// refineWithPattern() with the bitmap `bm` as the pattern.
bool fitBitmap(TagDetection& t, const TagBitmap& bm, const PlaneImage& plane, const float* xs, const float* ys,
			   const float* zs, const float* is, const PatternRefinementParams& p)
{
	const double cell0 = t.size / bm.borderCells;
	// The points' own footprint blurs the pattern; a map merged from
	// drifting or badly deskewed views blurs it more (cells smeared over a
	// neighbour). The model takes the blur that fits the points best at the
	// decoded pose, so a blurred tag is judged against a blurred bitmap, not
	// a sharp one.
	const double footprint = kPointFootprintSpacings * plane.localSpacing / cell0;
	// A smeared blur below the footprint's is the footprint's model again.
	std::vector<std::shared_ptr<const PatternModel>> models = {std::make_shared<const PatternModel>(bm, footprint)};
	for (double smeared : kSmearedBlurCells)
		models.push_back(footprint < smeared ? smearedModels().get(bm, smeared) : models.front());

	// Tag-plane coordinates of the inliers in the initial tag frame.
	const Eigen::Isometry3d T0 = t.pose, toTag = T0.inverse();
	std::vector<Eigen::Vector2d> q;
	std::vector<double> I;
	// The points on the grid at the decoded pose: the same set throughout
	// the fit (see PatternModel::sample), so that the cost is continuous.
	const double reach = 0.5 * bm.cells * cell0;
	for (uint32_t i : plane.inliers)
	{
		const Eigen::Vector3d l = toTag * Eigen::Vector3d(xs[i], ys[i], zs[i]);
		if (std::abs(l.x()) > reach || std::abs(l.y()) > reach) continue;
		q.emplace_back(l.x(), l.y());
		I.push_back(is[i]);
	}
	if (q.size() < kMinPoints) return false;

	// Residuals with the intensity gain and offset solved in closed form.
	const PatternModel* model = models.front().get();
	const PatternModel* chosen = nullptr;
	auto evaluate = [&](const FitState& s, bool wantResiduals) {
		Evaluation e;
		const RefinedFrame frame(s, cell0);
		std::vector<double> m(q.size());
		double sm = 0, sI = 0, smm = 0, smI = 0, sII = 0;
		for (size_t k = 0; k < q.size(); k++)
		{
			const Eigen::Vector2d at = frame.inCells(q[k]);
			const double v = m[k] = model->sample(at.x(), at.y());
			sm += v;
			sI += I[k];
			smm += v * v;
			smI += v * I[k];
			sII += I[k] * I[k];
		}
		const double n = static_cast<double>(q.size());
		const double vm = smm / n - (sm / n) * (sm / n), vI = sII / n - (sI / n) * (sI / n);
		const double cov = smI / n - (sm / n) * (sI / n);
		e.correlation = vm > 0 && vI > 0 ? cov / std::sqrt(vm * vI) : 0;
		const double gain = vm > 0 ? cov / vm : 0, offset = sI / n - gain * sm / n;
		e.cost = std::max(0.0, vI - gain * cov);
		if (wantResiduals)
		{
			e.residuals.resize(static_cast<long>(q.size()));
			for (size_t k = 0; k < q.size(); k++) e.residuals(static_cast<long>(k)) = I[k] - (offset + gain * m[k]);
		}
		return e;
	};

	FitState s;
	Evaluation best;
	for (const auto& candidate : models)
	{
		model = candidate.get();
		const Evaluation e = evaluate(s, true);
		if (chosen == nullptr || e.correlation > best.correlation) best = e, chosen = candidate.get();
	}
	model = chosen;
	// Numeric Jacobian of the residuals in the first n of (theta, dx, dy,
	// logScale).
	auto jacobian = [&](const FitState& at, const Eigen::VectorXd& r0, int n) {
		const double steps[4] = {kAngleStep, kShiftStepCells * cell0, kShiftStepCells * cell0, kLogScaleStep};
		Eigen::MatrixXd J(r0.size(), n);
		for (int j = 0; j < n; j++)
		{
			FitState d = at;
			double* f[4] = {&d.theta, &d.dx, &d.dy, &d.logScale};
			*f[j] += steps[j];
			J.col(j) = (evaluate(d, true).residuals - r0) / steps[j];
		}
		return J;
	};
	if (p.refine)
	{
		const int nParams = p.estimateSize ? 4 : 3;
		double lambda = kInitialDamping;
		for (int it = 0; it < p.iterations; it++)
		{
			const Eigen::MatrixXd J = jacobian(s, best.residuals, nParams);
			Eigen::MatrixXd H = J.transpose() * J;
			const Eigen::VectorXd g = J.transpose() * best.residuals;
			bool improved = false;
			for (int tries = 0; tries < kDampedTries && !improved; tries++)
			{
				Eigen::MatrixXd Hd = H;
				Hd.diagonal() *= (1 + lambda);
				const Eigen::VectorXd delta = -Hd.ldlt().solve(g);
				FitState cand = s;
				cand.theta += delta(0);
				cand.dx += delta(1);
				cand.dy += delta(2);
				if (nParams == 4) cand.logScale += delta(3);
				Evaluation e = evaluate(cand, true);
				if (e.cost < best.cost)
				{
					s = cand;
					best = e;
					lambda = std::max(kMinDamping, lambda / kDampingDown);
					improved = true;
				}
				else
					lambda *= kDampingUp;
			}
			if (!improved) break;
		}
		// In-plane covariance, the sandwich H^-1 (sum over cells of g g^T)
		// H^-1 with g the gradient of one tag cell's residuals: within a cell
		// they are correlated (the beam footprint, and a model blur that is
		// not the sensor's, spread one error over neighbours), and treating
		// thousands of points as independent reported in-plane angles 2-5x
		// too tight (devset: 0.02-0.05 deg reported, 0.1-0.25 deg off).
		{
			const Eigen::MatrixXd J = jacobian(s, best.residuals, 3);
			const Eigen::Matrix3d Hinv = (J.transpose() * J).inverse();
			const RefinedFrame frame(s, cell0);
			std::map<std::pair<int, int>, Eigen::Vector3d> perCell;
			for (size_t k = 0; k < q.size(); k++)
			{
				const Eigen::Vector2d at = frame.inCells(q[k]);
				const std::pair<int, int> key(static_cast<int>(std::floor(at.x())), static_cast<int>(std::floor(at.y())));
				auto it = perCell.try_emplace(key, Eigen::Vector3d::Zero()).first;
				it->second += J.row(static_cast<long>(k)).transpose() * best.residuals(static_cast<long>(k));
			}
			Eigen::Matrix3d meat = Eigen::Matrix3d::Zero();
			for (const auto& [key, g] : perCell) meat += g * g.transpose();
			Eigen::Matrix3d cov = Hinv * meat * Hinv;
			// The sandwich is the cost's slope at the fit. Where the points
			// leave the pattern free to slide (scan rows about a cell apart,
			// crossing every cell at the same height), the fit lands anywhere
			// in that range, up to half of it off, while the slope there says
			// millimetres: the range counts as a uniform uncertainty.
			const RefinedFrame fitted(s, cell0);
			std::vector<Eigen::Vector2d> inCells(q.size());
			for (size_t k = 0; k < q.size(); k++) inCells[k] = fitted.inCells(q[k]);
			for (int a = 0; a < 2; a++)
			{
				const double range = freeShift(inCells, bm, a) * fitted.cell;
				cov(1 + a, 1 + a) = std::max(cov(1 + a, 1 + a), range * range / 12);
			}
			if (cov.allFinite())
			{
				// Tag-frame in-plane translation and rotation about the normal (the
				// fit's axes are the initial frame's).
				setTagFrameCovariance(t.covariance, T0.linear(), false, {0, 1}, cov.bottomRightCorner<2, 2>());
				setTagFrameCovariance(t.covariance, T0.linear(), true, {2}, cov.topLeftCorner<1, 1>());
			}
		}
	}
	t.patternFit = best.correlation;
	t.patternPoints = static_cast<int>(q.size());
	if (p.minPatternFit <= 0)
	{
		if (best.correlation < p.minPatternFit) return false;
	}
	else
	{
		// The points in the refined tag frame, in cells, and the model there.
		const RefinedFrame frame(s, cell0);
		std::vector<Eigen::Vector2d> inCells(q.size());
		std::vector<double> m(q.size());
		for (size_t k = 0; k < q.size(); k++)
		{
			inCells[k] = frame.inCells(q[k]);
			m[k] = model->sample(inCells[k].x(), inCells[k].y());
		}
		if (binnedCorrelation(inCells, I, m) < p.minPatternFit) return false;
	}

	Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();
	delta.linear() = Eigen::AngleAxisd(s.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
	delta.translation() = Eigen::Vector3d(s.dx, s.dy, 0);
	t.pose = T0 * delta;
	t.size *= std::exp(s.logScale);
	t.corners = cornersFromPose(t.pose, t.size);
	return true;
}
}  // namespace

bool refineWithPattern(TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys, const float* zs,
					   const float* is, const PatternRefinementParams& p)
{
	return fitBitmap(t, renderTagBitmap(t.family, t.id), plane, xs, ys, zs, is, p);
}

bool placeByFrame(TagDetection& t, const PlaneImage& plane, const float* xs, const float* ys, const float* zs,
				  const float* is, const PatternRefinementParams& p)
{
	// The code cells are mid-grey in the model. Weighing them 0 instead
	// (a blurred mask) placed worse on the devset's scale_1m with 2 cm of
	// noise (5 -> 4 tags of 10; the grey keeps the ring's inner edge in
	// the fit).
	PatternRefinementParams placing = p;
	placing.refine = true;
	placing.minPatternFit = 0;  // the code cells' colours are no part of the model: no fit to judge
	return fitBitmap(t, frameBitmap(t.family), plane, xs, ys, zs, is, placing);
}

}  // namespace tagmap
