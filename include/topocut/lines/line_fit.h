#pragma once
// Total-least-squares line fit in polar form (Borges & Aldon 2004, eqs. 7-9): the line
// x cos(alpha) + y sin(alpha) = rho minimising the sum of squared perpendicular distances, with
// rho >= 0 and alpha in (-pi, pi]. Optionally weighted (fuzzy memberships).
#include <span>

#include "topocut/core/geometry.h"

namespace topocut {

struct LineFit {
  double rho = 0.0;    // distance of the line from the origin, >= 0
  double alpha = 0.0;  // direction of the line's normal, in (-pi, pi]
  Point2 centroid;     // (weighted) mean of the points, which lies on the line
  double weight = 0.0;  // number of points, or the sum of the weights
  double sigma = 0.0;   // (weighted) root-mean-square perpendicular distance of the points
};

// Fits a line to the points. Exactly collinear points give their line exactly (up to rounding); a
// single point or identical points give the line through them perpendicular to the direction from
// the origin (alpha = bearing of the point), the natural reading for a laser that saw one spot.
// An empty span gives a zero LineFit with weight 0.
LineFit fit_line(std::span<const Point2> points);

// Weighted fit; weights must be >= 0 and as many as points (throws Error otherwise). Points of
// zero weight are ignored; all-zero weights give a zero LineFit with weight 0.
LineFit fit_line(std::span<const Point2> points, std::span<const double> weights);

// Polar parameters of the line through a point with the given normal direction (any angle, any
// sign), normalised to rho >= 0, alpha in (-pi, pi].
LineFit polar_line(const Point2& on_line, double normal_angle);

// Signed perpendicular distance of p from the line (positive on the side away from the origin).
double signed_distance(double rho, double alpha, const Point2& p);

// The angle wrapped into (-pi, pi].
double normalize_angle(double angle);

// Smallest absolute difference between two angles, in [0, pi].
double angle_difference(double a, double b);

}  // namespace topocut
