// Exact Fresnel reflectance of unpolarized light at an interface (course report §2.2, after
// Tessendorf 2001 §3.3):
//   R = ½·( sin²(θt − θi)/sin²(θt + θi) + tan²(θt − θi)/tan²(θt + θi) ),  n_a·sin θi = n_w·sin θt.
// Evaluated in the equivalent amplitude form, which has no 0/0 at normal incidence:
//   r_s = (n_a·cos θi − n_w·cos θt)/(n_a·cos θi + n_w·cos θt)   (= −sin(θi−θt)/sin(θi+θt))
//   r_p = (n_w·cos θi − n_a·cos θt)/(n_w·cos θi + n_a·cos θt)   (=  tan(θi−θt)/tan(θi+θt))
//   R = ½·(r_s² + r_p²);  T = 1 − R.
// cosIncident is cos θi on the side of index n1; the light goes into index n2.
float fresnelReflectance(float cosIncident, float n1, float n2) {
  float cosI = clamp(cosIncident, 0.0, 1.0);
  float sinT = n1 / n2 * sqrt(max(0.0, 1.0 - cosI * cosI));
  if (sinT >= 1.0) return 1.0;  // total internal reflection
  float cosT = sqrt(1.0 - sinT * sinT);
  float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  float rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
  return 0.5 * (rs * rs + rp * rp);
}
