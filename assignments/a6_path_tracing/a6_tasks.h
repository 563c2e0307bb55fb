// Assignment 6 -- Monte Carlo path tracing: the rendering equation
//   L(x, wo) = Le(x, wo) + integral over the hemisphere of f(x, wo, wi) L(x', -wi) cos(theta_i) dwi
// estimated by random paths. The four tasks you write; each lives in
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

// A6.4 The GGX microfacet distribution (Trowbridge and Reitz 1975; Walter
// et al. 2007) of a rough metal or rough glass. All directions are unit
// vectors in the local frame, z = the surface's normal; alpha in (0, 1] is
// the roughness (a scene's "roughness"). The framework builds the BSDFs
// from these three (bsdf.cpp): a metal's f = F(wo.h) D(h) G2 / (4 cos_o cos_i).
//
// The density of microfacet normals h, per steradian of h and per unit of
// the surface's area: 1 / (pi alpha^2 cos^4(theta_h) (1 + tan^2(theta_h) / alpha^2)^2)
// for h.z > 0, else 0. Its projection integrates to 1: integral D(h) h.z dh = 1.
float ggxDistribution(const Vec3& h, float alpha);
// Smith's masking G1(w) = 1 / (1 + Lambda(w)) with
// Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2(theta_w))) / 2: the fraction of
// the microsurface seen from w that is not hidden by other facets; 1 at
// w = n, 0 at and below the horizon.
float smithMasking(const Vec3& w, float alpha);
// A microfacet normal drawn from the normals visible from wo (wo.z > 0),
// density D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z (Heitz 2018, "Sampling
// the GGX distribution of visible normals", JCGT 7(4)): stretch wo by alpha,
// sample the projected hemisphere it sees with u, unstretch the normal.
Vec3 sampleGgxVisibleNormal(const Vec3& wo, float alpha, Vec2 u);

}  // namespace ll::a6
