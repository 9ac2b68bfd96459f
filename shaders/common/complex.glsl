// Complex numbers as vec2(real, imaginary).

vec2 complexMultiply(vec2 a, vec2 b) {
  return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

vec2 complexConjugate(vec2 a) {
  return vec2(a.x, -a.y);
}

// i·a
vec2 timesI(vec2 a) {
  return vec2(-a.y, a.x);
}
