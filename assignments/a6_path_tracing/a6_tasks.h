// Assignment 6 -- Monte Carlo path tracing: the rendering equation
//   L(x, wo) = Le(x, wo) + integral over the hemisphere of f(x, wo, wi) L(x', -wi) cos(theta_i) dwi
// estimated by random paths. The three functions you write; each lives in
// its own .cpp file between the markers of its task ID. The technique `path`
// (path_technique.cpp, framework code worth reading) calls them. Until you
// write one, its stub reports the task as missing and the task's reference
// (the course's solution, object code) answers in its place, the pixels
// striped, so the tasks can be done in any order (README.md: --reference).
#pragma once

#include "light_sampler.h"
#include "core/math.h"
#include "render/tracer.h"

namespace ll::a6 {

// A6.1 Cosine-weighted hemisphere sampling. Maps a uniform point u in
// [0,1)^2 to a unit direction in the local frame (z = the surface normal,
// z >= 0) whose density over solid angle is cos(theta) / pi -- the
// diffuse BSDF's cosine factor cancels in f cos / pdf. Malley's method:
// a uniform point on the unit disk, lifted to the hemisphere.
Vec3 sampleCosineHemisphere(Vec2 u);
// The density of that sampling for a direction with cos(theta) = cosTheta,
// per steradian: cos(theta) / pi above the horizon, 0 at or below it.
float cosineHemispherePdf(float cosTheta);

// A6.2 Next-event estimation. The radiance arriving at x from one light
// sample, towards wo, through the BSDF:
//   f(wo, wi) |n.wi| Le V(x, y) / p(wi)     (weighted by MIS, see below)
// where p(wi) is the light sample's density converted from area to solid
// angle: p(wi) = pdfArea * |x - y|^2 / cos(theta_y). V is visibility: cast a
// shadow ray with visible() (bsdf.h) unless light.castShadow is false.
// Delta lights (point, directional) are not sampled by area: their pdf is
// the probability of choosing them, and they arrive with irradiance
// pi I / r^2 (point) or pi I (directional) -- lecture units, in which a
// diffuse surface shows kd I cos / r^2 (see bsdf.h). With `mis`, an area
// light's term is weighted by powerHeuristic(p(wi), bsdf.pdf(wo, wi)) so
// that it adds up with the BSDF-sampled rays that hit the same light;
// without, by 1. Return 0 for a light behind its emitting side or behind x.
Rgb nextEventEstimate(const ShadingPoint& x, const LightSample& light, const Bsdf& bsdf, const Tracer& tracer,
                      bool mis);

// A6.3 Russian roulette. Ends long paths without bias: the path goes on
// with probability q = clamp(max component of throughput, 0.05, 0.95) and
// then carries throughput / q; it ends when u >= q. u is uniform in [0, 1).
// Returns whether the path goes on (and divides `throughput` by q if so).
bool russianRoulette(Rgb& throughput, float u);

}  // namespace ll::a6
