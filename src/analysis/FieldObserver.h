#pragma once
// Coarse-grained continuum fields around the intruder (docs/FIELDS.md; paper eqs. 3.1-3.5, figures 9-11):
// area fraction, velocity and stress on a square grid in the intruder's frame, averaged over the
// frames taken at each chosen drive phase. An observer: it reads a World and never changes it.
//
// Definitions (docs/FIELDS.md has the derivations and the measured test numbers):
//   W(r)   = exp(-|r|^2 / w^2) / (pi w^2), truncated (not renormalised) at |r| <= 3w, which drops a
//            fraction exp(-9) = 1.23e-4 of its weight.
//   Phi(p) = sum_i a_i W(p - r_i),  a_i = pi d_i^2 / 4, over grains only (not the intruder, not the
//            frozen base): inside the intruder Phi falls to 0, as the paper's masked figures.
//   v(p)   = sum_i a_i v_i W(p - r_i) / Phi(p); over frames the numerator and Phi are averaged
//            separately, then divided.
//   sigma(p) = sum over touching contacts c of f_c (x) b_c * integral_0^1 W(p - r_i - s b_c) ds
//            (Glasser & Goldhirsch), f_c the force on particle i from its partner j and
//            b_c = r_j - r_i the branch vector from i to j. A repulsive contact has f . b < 0, so
//            compression is negative and P = -(sxx + syy) / 2 is positive. A contact counts at p
//            when the closest point of its branch segment lies within 3w of p, and then with the
//            whole, exact line integral (error functions). Contacts are grain-grain, grain-base
//            and grain-intruder (the intruder is part of the material: its contacts carry stress;
//            the branch runs from the grain centre to the intruder atom centre).
//   kinetic (optional): sigma_k(p) = -sum_i m_i (v_i - v(p)) (x) (v_i - v(p)) W(p - r_i), with
//            v(p) the same frame's velocity field.
// Units: lengths in d, stress in [m g / d] (force per unit length: the 2D stress).
//
// Cost: one pass over the grains and one over the contacts, each culled to the grid's bounding box
// plus the 3w cut; per grain or contact only the grid points within 3w are visited. OpenMP threads
// take bands of grid rows, so the result is bitwise the same for any thread count.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/BinaryStream.h"
#include "io/RunConfig.h"

namespace wiggle {

class World;

// The Glasser-Goldhirsch weight of a segment: integral over s in [0,1] of W(q - s b), with
// W(r) = exp(-|r|^2/w^2)/(pi w^2) (not cut), q = point minus segment start, b the segment. Closed
// form with error functions (complementary ones where the plain form would cancel):
//   a = q . b / |b|, h = |q x b| / |b|, L = |b|,
//   I = exp(-h^2/w^2) / (2 sqrt(pi) w L) * [erf(a/w) + erf((L - a)/w)].
double segmentGaussianWeight(double qx, double qy, double bx, double by, double w);

// Frame-averaged values at one grid point of one phase (what a CSV row holds).
struct FieldSample {
  double phi = 0.0;                  // area fraction
  double vx = 0.0, vy = 0.0;         // velocity [sqrt(g d)]; NaN where the averaged Phi is 0
  double sxx = 0.0, sxy = 0.0, syx = 0.0, syy = 0.0;  // stress, compression negative [m g / d]
  double pressure = 0.0;             // -(sxx + syy) / 2
  double symmetricShear() const { return 0.5 * (sxy + syx); }  // fields.csv's sxy
};

class FieldObserver {
 public:
  // Throws wiggle::Error on a bad definition (non-positive width or spacing, negative radius, a
  // grid of more than 4001 points per side).
  FieldObserver(const FieldsDef& def, double boxWidth);

  // One frame of phase set `phaseIndex` (index into def.phases), with the grid centred on the
  // intruder's centre. Reads state only. Throws if the world has no intruder.
  void addFrame(const World& world, std::size_t phaseIndex);
  // The same with the grid centred at (centreX, centreY): addFrame calls this (one code path).
  void addFrameAt(const World& world, std::size_t phaseIndex, double centreX, double centreY);

  std::uint64_t frames(std::size_t phaseIndex) const;
  std::size_t phaseCount() const { return def_.phases.size(); }
  std::size_t pointsPerSide() const { return n_; }
  // Grid coordinate along x or y of index k, relative to the centre [d]: symmetric about 0.
  double gridCoordinate(std::size_t k) const;
  // Frame average at grid point (ix, iy) (x index, y index) of a phase; throws if it has no frames.
  FieldSample sample(std::size_t phaseIndex, std::size_t ix, std::size_t iy) const;

  // Every grid point of every phase in fields.csv's row order (phase, then y, then x fastest), with
  // its frame count and, when that is not 0, its frame average (else none).
  struct Row {
    double phase, x, y;
    std::uint64_t frames;
    const FieldSample* sample;  // null for a phase without frames
  };
  void forEachRow(const std::function<void(const Row&)>& visit) const;

  // CSV `phase,x,y,phi,vx,vy,sxx,sxy,syy,pressure,frames`, one row per grid point per phase (x
  // fastest); sxy is the symmetric part (sxy + syx)/2. Values are empty for a phase without frames,
  // and vx, vy empty where the averaged Phi is 0. Written to PATH.tmp, then renamed over PATH.
  void writeCsv(const std::string& path) const;

  // Accumulators, for checkpoints: a resumed run continues bit for bit. load() throws if the saved
  // grid or phases do not match this observer's definition.
  void save(BinaryWriter& out) const;
  void load(BinaryReader& in);

 private:
  struct Grid {  // one set of accumulated fields, n*n points each, x fastest
    std::vector<double> phi, momX, momY, sxx, sxy, syx, syy;
    void resize(std::size_t points);
    void zero();
  };
  struct Rows {  // a thread's band of grid rows [begin, end)
    std::size_t begin, end;
  };
  void depositGrains(const World& world, double cx, double cy, Rows rows, std::vector<double>& ex,
                     std::vector<double>& ey);
  void depositContacts(const World& world, double cx, double cy, Rows rows);
  void depositSegment(double px, double py, double bx, double by, double fx, double fy, Rows rows);
  void depositKinetic(const World& world, double cx, double cy, Rows rows);

  FieldsDef def_;
  double boxWidth_;          // [d]
  std::size_t n_ = 0;        // grid points per side
  double cut_ = 0.0;         // 3w [d]
  double reach_ = 0.0;       // a grain farther than this from the centre (in x or y) adds nothing [d]
  double invWidthSq_ = 0.0;  // 1 / w^2
  double pointNorm_ = 0.0;   // 1 / (pi w^2): the Gaussian's normalisation in 2D
  std::vector<std::uint64_t> frames_;
  std::vector<Grid> sums_;   // per phase: sums over frames
  Grid frame_;               // the current frame (scratch)
};

}  // namespace wiggle
