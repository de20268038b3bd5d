// Loop removal, methods 1 and 2 (Misawa, Chiba, Saito 1987, Sec. 4.4): see loop_removal.hpp.
#include "contour/loop_removal.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "contour/clipping.hpp"
#include "contour/crossings.hpp"

namespace sansui::contour {
namespace {

/// One visit of a crossing while walking along the ring.
struct Event {
  double position;  ///< segment index + parameter along it
  int crossing;     ///< which crossing
  int partner;      ///< index (in the sorted event list) of the other visit
};

std::vector<Event> events_of(const std::vector<Crossing>& crossings) {
  std::vector<Event> events;
  events.reserve(2 * crossings.size());
  for (std::size_t c = 0; c < crossings.size(); ++c) {
    events.push_back({crossings[c].segment_a + crossings[c].t_a, static_cast<int>(c), -1});
    events.push_back({crossings[c].segment_b + crossings[c].t_b, static_cast<int>(c), -1});
  }
  std::sort(events.begin(), events.end(),
            [](const Event& a, const Event& b) { return a.position != b.position ? a.position < b.position : a.crossing < b.crossing; });
  std::vector<int> first(crossings.size(), -1);
  for (std::size_t e = 0; e < events.size(); ++e) {
    int& seen = first[static_cast<std::size_t>(events[e].crossing)];
    if (seen < 0) {
      seen = static_cast<int>(e);
    } else {
      events[e].partner = seen;
      events[static_cast<std::size_t>(seen)].partner = static_cast<int>(e);
    }
  }
  return events;
}

/// Ring vertices whose index lies strictly after position `from` and at or before `to` (cyclic
/// positions measured from the same origin, from <= to, possibly beyond n).
void append_vertices(const Ring& ring, double from, double to, Ring& out) {
  const auto n = static_cast<long>(ring.size());
  for (long v = static_cast<long>(std::floor(from)) + 1; v <= static_cast<long>(std::floor(to)); ++v)
    if (static_cast<double>(v) > from) out.push_back(ring[static_cast<std::size_t>(((v % n) + n) % n)]);
}

}  // namespace

Ring remove_loops_by_walk(const Ring& ring, int threshold) {
  const auto crossings = self_crossings(ring);
  if (crossings.empty()) return ring;
  const auto events = events_of(crossings);
  const auto n = static_cast<double>(ring.size());
  const std::size_t count = events.size();
  // Start in the stretch between consecutive crossings with the most vertices (the paper: one with
  // at least `threshold` points); `threshold` only breaks ties in favour of long stretches.
  std::size_t best = 0;
  long best_vertices = -1;
  for (std::size_t e = 0; e < count; ++e) {
    const double from = events[e].position;
    const double to = e + 1 < count ? events[e + 1].position : events[0].position + n;
    const long vertices = static_cast<long>(std::floor(to)) - static_cast<long>(std::floor(from));
    if (vertices > best_vertices) best_vertices = vertices, best = e;
  }
  (void)threshold;
  const double from = events[best].position;
  const double to = best + 1 < count ? events[best + 1].position : events[0].position + n;
  const double start = std::floor(0.5 * (from + to));  // a vertex inside that stretch
  auto relative = [&](double position) {
    double r = position - start;
    while (r < 0.0) r += n;
    while (r >= n) r -= n;
    return r;
  };
  std::vector<std::size_t> order(count);
  for (std::size_t e = 0; e < count; ++e) order[e] = e;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return relative(events[a].position) < relative(events[b].position); });
  std::vector<double> rank(count);
  for (std::size_t e = 0; e < count; ++e) rank[e] = relative(events[e].position);

  Ring out;
  out.push_back(ring[static_cast<std::size_t>(start) % ring.size()]);
  double cursor = 0.0;  // relative position walked so far
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t e = order[k];
    if (rank[e] <= cursor) continue;  // inside an excursion already cut out
    const double partner = rank[static_cast<std::size_t>(events[e].partner)];
    if (partner <= rank[e]) continue;  // its first visit was cut out with an excursion
    append_vertices(ring, start + cursor, start + rank[e], out);
    out.push_back(crossings[static_cast<std::size_t>(events[e].crossing)].at);
    cursor = partner;  // jump to the second visit
  }
  append_vertices(ring, start + cursor, start + n - 1e-9, out);
  remove_duplicates(out);
  return out;
}

std::vector<Ring> remove_loops_by_faces(const Ring& ring, int threshold) {
  const auto crossings = self_crossings(ring);
  if (crossings.empty()) return {ring};
  const auto events = events_of(crossings);
  const std::size_t arcs = events.size();  // arc k runs from event k to event k+1
  const auto n = static_cast<double>(ring.size());
  // The polyline of every arc, from one crossing to the next.
  std::vector<Ring> polylines(arcs);
  for (std::size_t k = 0; k < arcs; ++k) {
    const Event& a = events[k];
    const Event& b = events[(k + 1) % arcs];
    const double to = k + 1 < arcs ? b.position : b.position + n;
    Ring& line = polylines[k];
    line.push_back(crossings[static_cast<std::size_t>(a.crossing)].at);
    append_vertices(ring, a.position, to, line);
    line.push_back(crossings[static_cast<std::size_t>(b.crossing)].at);
  }
  // Half-edges: 2k is arc k forward, 2k+1 backward. Outgoing half-edges at every crossing, by angle.
  auto tail_direction = [&](std::size_t half) {
    const Ring& line = polylines[half / 2];
    const bool forward = half % 2 == 0;
    const Point origin = forward ? line.front() : line.back();
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Point p = forward ? line[i] : line[line.size() - 1 - i];
      if (p.x != origin.x || p.y != origin.y) return p - origin;
    }
    return Point{1.0, 0.0};
  };
  auto tail_vertex = [&](std::size_t half) { return half % 2 == 0 ? events[half / 2].crossing : events[(half / 2 + 1) % arcs].crossing; };
  std::vector<std::vector<std::size_t>> outgoing(crossings.size());
  for (std::size_t h = 0; h < 2 * arcs; ++h) outgoing[static_cast<std::size_t>(tail_vertex(h))].push_back(h);
  std::vector<double> angle(2 * arcs);
  for (std::size_t h = 0; h < 2 * arcs; ++h) {
    const Point d = tail_direction(h);
    angle[h] = std::atan2(d.y, d.x);
  }
  for (auto& list : outgoing)
    std::sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) { return angle[a] != angle[b] ? angle[a] < angle[b] : a < b; });
  // next(h): at h's head, the outgoing half-edge just clockwise of h's twin keeps the face on the left.
  auto next_of = [&](std::size_t h) {
    const std::size_t twin = h ^ 1u;
    const auto& list = outgoing[static_cast<std::size_t>(tail_vertex(twin))];
    const auto it = std::find(list.begin(), list.end(), twin);
    const std::size_t i = static_cast<std::size_t>(it - list.begin());
    return list[(i + list.size() - 1) % list.size()];
  };
  // Trace faces.
  std::vector<int> face_of(2 * arcs, -1);
  std::vector<Ring> faces;
  std::vector<int> segments;
  for (std::size_t h0 = 0; h0 < 2 * arcs; ++h0) {
    if (face_of[h0] >= 0) continue;
    const int face = static_cast<int>(faces.size());
    Ring polygon;
    int edges = 0;
    std::size_t h = h0;
    for (std::size_t guard = 0; guard <= 2 * arcs && face_of[h] < 0; ++guard) {
      face_of[h] = face;
      const Ring& line = polylines[h / 2];
      edges += static_cast<int>(line.size()) - 1;
      if (h % 2 == 0) {
        polygon.insert(polygon.end(), line.begin(), line.end() - 1);
      } else {
        polygon.insert(polygon.end(), line.rbegin(), line.rend() - 1);
      }
      h = next_of(h);
    }
    faces.push_back(std::move(polygon));
    segments.push_back(edges);
  }
  // Winding numbers: the outer face (the one clockwise face) is 0; crossing an arc from its right
  // to its left adds one.
  const std::size_t face_count = faces.size();
  std::vector<int> winding(face_count, 0);
  std::vector<bool> known(face_count, false);
  std::size_t outer = 0;
  for (std::size_t f = 0; f < face_count; ++f)
    if (signed_area(faces[f]) < signed_area(faces[outer])) outer = f;
  std::deque<std::size_t> queue{outer};
  known[outer] = true;
  while (!queue.empty()) {
    const std::size_t f = queue.front();
    queue.pop_front();
    for (std::size_t h = 0; h < 2 * arcs; ++h) {
      if (static_cast<std::size_t>(face_of[h]) != f) continue;
      const auto other = static_cast<std::size_t>(face_of[h ^ 1u]);
      if (known[other]) continue;
      // f lies left of half-edge h; the twin's face lies right of it, i.e. left of the twin.
      winding[other] = winding[f] + (h % 2 == 0 ? -1 : 1);
      known[other] = true;
      queue.push_back(other);
    }
  }
  std::vector<Ring> kept;
  std::size_t largest = face_count;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (f == outer || winding[f] <= 0) continue;
    if (largest == face_count || signed_area(faces[f]) > signed_area(faces[largest])) largest = f;
    if (segments[f] >= threshold) kept.push_back(faces[f]);
  }
  if (kept.empty() && largest < face_count) kept.push_back(faces[largest]);
  return positive_region(kept);
}

std::vector<Ring> remove_loops(const Ring& ring, const LoopRemovalParams& params) {
  if (params.method == 1) return remove_loops_by_faces(ring, params.threshold);
  Ring walked = remove_loops_by_walk(ring, params.threshold);
  if (walked.size() >= 3 && signed_area(walked) > 0.0 && self_crossings(walked).empty()) return {std::move(walked)};
  return positive_region(ring);
}

}  // namespace sansui::contour
