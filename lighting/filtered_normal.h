#pragma once
// Lighting a filtered normal: the mean of the leaf normals a texel of a normal page stands for
// (a bake's blur, mip levels), kept short the more they disagree (Toksvig 2005; shaders/
// shading.glsl filtered_normal). shaders/shading.glsl filtered_clamped_cosine mirrors this
// function line for line; it is here to be tested by hand.
namespace sylva {

// The sun's clamped cosine E[max(n.l, 0)] over the leaves a filtered normal n averages, from the
// mean mu = n.l and the spread w = 1 - |n|: max(mu, 0) outside [-w, w] and the parabola
// (mu + w)^2 / 4w inside, which meets both lines with their slopes (value w and slope 1 at
// mu = w, value and slope 0 at mu = -w). Exact for a unit normal (w = 0: max(n.l, 0)) and for
// normals spread evenly over the sphere (w = 1, mu = 0: 1/4, the sphere's mean clamped cosine).
// The translucent light of the leaves facing away, E[max(-n.l, 0)], is this minus mu. Lit with
// max(mu, 0) instead, a filtered normal loses the sunlight of the leaves that face the sun more
// than their mean and all the translucent light, so billboards, clouds and shells came out greyer
// than their leaves. Our own smooth clamp (no paper gives the diffuse case).
inline float filtered_clamped_cosine(float mu, float w) {
    if (mu >= w) return mu;
    if (mu <= -w) return 0.0f;
    return (mu + w) * (mu + w) / (4.0f * w);
}

}  // namespace sylva
