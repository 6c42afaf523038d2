// report.html's page: draws the run's data (the JSON in #report-data) with Leaflet. Works
// offline: no tiles, no fetches. When done it writes what it drew into <body data-*> (status,
// features per route, errors) for the headless-browser test and for anyone inspecting the page.
(function() {
'use strict';
var body = document.body;
var errors = [];
window.addEventListener('error', function(e) {
  errors.push(String(e.message));
  body.setAttribute('data-errors', String(errors.length));
  body.setAttribute('data-last-error', String(e.message));
});
body.setAttribute('data-errors', '0');

var data = JSON.parse(document.getElementById('report-data').textContent);

// Viridis-like ramp for 0..1.
var STOPS = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
function ramp(t) {
  t = Math.max(0, Math.min(1, isFinite(t) ? t : 0)) * (STOPS.length - 1);
  var i = Math.min(Math.floor(t), STOPS.length - 2), f = t - i, a = STOPS[i], b = STOPS[i + 1];
  return 'rgb(' +
      [0, 1, 2]
          .map(function(k) {
            return Math.round(a[k] + f * (b[k] - a[k]));
          })
          .join(',') +
      ')';
}
function range(values) {
  var lo = Infinity, hi = -Infinity;
  values.forEach(function(v) {
    if (isFinite(v)) {
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    }
  });
  if (!isFinite(lo)) return [0, 1];
  return hi > lo ? [lo, hi] : [lo, lo + 1];
}
function el(tag, attrs, text) {
  var e = document.createElement(tag);
  Object.keys(attrs || {}).forEach(function(k) {
    e.setAttribute(k, attrs[k]);
  });
  if (text !== undefined) e.textContent = text;
  return e;
}
function fmt(v, d) {
  return isFinite(v) ? Number(v).toFixed(d) : '–';
}

// --- page skeleton
var header = el('header');
header.appendChild(el('h1', {}, data.title));
header.appendChild(
    el('div', {'class': 'sub'},
       data.net + (data.geo ? ' (WGS84)' : ' (net x/y in metres: no geo-reference)')));
body.appendChild(header);
var main = el('div', {id: 'main'});
var mapDiv = el('div', {id: 'map'});
var side = el('div', {id: 'side'});
main.appendChild(mapDiv);
main.appendChild(side);
body.appendChild(main);
var tables = el('div', {id: 'tables'});
body.appendChild(tables);

var map = L.map(
    mapDiv,
    data.geo ? {preferCanvas: true} :
               {preferCanvas: true, crs: L.CRS.Simple, minZoom: -6, maxZoom: 6, zoomSnap: 0.25});
L.control.scale({imperial: false}).addTo(map);

function polyline(pts, style, tip) {
  var line = L.polyline(pts, style);
  if (tip) line.bindTooltip(tip, {sticky: true});
  return line;
}

// --- layers shared by every planner
var streets = L.featureGroup(data.streets.map(function(s) {
  return polyline(s.pts, {color: '#9a9a9a', weight: 2}, (s.name || 'unnamed') + ' (' + s.id + ')');
}));
var wr = range(data.weights.map(function(w) {
  return w.w;
}));
var weights = L.featureGroup(data.weights.map(function(w) {
  return polyline(
      w.pts, {color: ramp((w.w - wr[0]) / (wr[1] - wr[0])), weight: 4},
      'graph edge ' + w.id + ': weight ' + fmt(w.w, 3));
}));

// --- per planner: route (one feature per SUMO edge driven), drift, trajectories
var featureCounts = [];
var planners = data.planners.map(function(p) {
  var nmax = 1;
  p.route.forEach(function(r) {
    nmax = Math.max(nmax, r.n);
  });
  var route = L.featureGroup(p.route.map(function(r, i) {
    return polyline(
        r.pts, {color: ramp(nmax > 1 ? (r.n - 1) / (nmax - 1) : 0.35), weight: 5, opacity: 0.85},
        '#' + (i + 1) + ' ' + (r.name || r.edge) + ': driven ' + r.n + 'x');
  }));
  featureCounts.push(p.name + ':' + route.getLayers().length);
  var dr = range(p.drift.map(function(d) {
    return d.pct;
  }));
  var drift = L.featureGroup(p.drift.map(function(d) {
    return polyline(
        d.pts, {color: ramp((d.pct - dr[0]) / (dr[1] - dr[0])), weight: 5},
        d.edge + ': drift along the street ' + fmt(d.pct, 2) + ' %, end to end ' +
            fmt(d.end, 2) + ' %, ATE ' + fmt(d.ate, 2) + ' m over ' + fmt(d.len, 0) + ' m');
  }));
  var traj = L.featureGroup();
  if (p.drive) {
    traj.addLayer(polyline(p.drive.gt, {color: '#111', weight: 2}, p.name + ' ground truth'));
    traj.addLayer(polyline(
        p.drive.est, {color: '#e0301e', weight: 2, dashArray: '4 4'},
        p.name + ' SLAM estimate (aligned)'));
  }
  return {p: p, route: route, drift: drift, traj: traj, nmax: nmax, drange: dr};
});

// --- the fleet (run --vehicles K): one more choice of route, each vehicle in its own colour.
// Vehicles drawn first are wider, so a street two vehicles share shows both colours.
var fleetCounts = [], fleetDriveCounts = [];
// Each evaluated vehicle's trajectories in its colour: ground truth wide and pale, the merged
// SLAM estimate (under the fleet's one alignment) dashed on top.
function fleetTrajectories(fv) {
  var traj = L.featureGroup(), drives = [];
  fv.forEach(function(v) {
    if (!v.drive || !v.drive.gt.length) return;
    traj.addLayer(
        polyline(v.drive.gt, {color: v.colour, weight: 5, opacity: 0.35}, v.id + ' ground truth'));
    traj.addLayer(polyline(
        v.drive.est, {color: v.colour, weight: 2, dashArray: '4 4'},
        v.id + ' SLAM estimate (merged map, aligned)'));
    drives.push({
      v: v,
      gt: L.circleMarker(
          [0, 0], {radius: 6, color: v.colour, fillColor: v.colour, fillOpacity: 0.9}),
      est:
          L.circleMarker([0, 0], {radius: 6, color: v.colour, fillColor: '#fff', fillOpacity: 0.9}),
      err: L.polyline([[0, 0], [0, 0]], {color: v.colour, weight: 1})
    });
    fleetDriveCounts.push(v.id + ':' + v.drive.gt.length);
  });
  return {traj: traj, drives: drives};
}
if (data.fleet) {
  var fv = data.fleet.vehicles, fleetRoute = L.featureGroup();
  fv.forEach(function(v, k) {
    v.route.forEach(function(r, i) {
      fleetRoute.addLayer(polyline(
          r.pts, {color: v.colour, weight: 3 + 3 * (fv.length - 1 - k), opacity: 0.9},
          v.id + ' #' + (i + 1) + ' ' + (r.name || r.edge)));
    });
    fleetCounts.push(v.id + ':' + v.route.length);
  });
  var ft = fleetTrajectories(fv);
  planners.push({
    p: {name: data.fleet.name + ' (' + fv.length + ' vehicles)', fleet: data.fleet, drive: null},
    route: fleetRoute,
    drift: L.featureGroup(),
    traj: ft.traj,
    fleetDrives: ft.drives,
    nmax: 1,
    drange: [0, 1]
  });
}

// --- controls
side.appendChild(el('h2', {}, 'Route'));
var select = el('select', {id: 'planner'});
planners.forEach(function(q, i) {
  select.appendChild(el('option', {value: String(i)}, q.p.name));
});
side.appendChild(select);
var toggles = {};
side.appendChild(el('h2', {}, 'Layers'));
[['streets', 'street network'], ['weights', 'streets by weight (depth-normal score)'],
 ['route', 'route: times driven'], ['drift', 'measured drift along each street'],
 ['traj', 'trajectories: ground truth / estimate']]
    .forEach(function(t) {
      var label = el('label');
      var box = el('input', {type: 'checkbox', id: 'show-' + t[0]});
      box.checked = t[0] !== 'weights' && t[0] !== 'drift';
      label.appendChild(box);
      label.appendChild(document.createTextNode(' ' + t[1]));
      side.appendChild(label);
      toggles[t[0]] = box;
    });
var legend = el('div', {'class': 'legend'});
side.appendChild(legend);
side.appendChild(el('h2', {}, 'Along the drive'));
var slider = el('input', {type: 'range', id: 'slider', min: '0', max: '0', value: '0'});
side.appendChild(slider);
var readout = el('div', {id: 'readout'});
side.appendChild(readout);
var chart = el('canvas', {id: 'chart', width: '300', height: '150'});
side.appendChild(chart);
var summary = el('div', {id: 'summary'});
side.appendChild(summary);

var gtMarker = L.circleMarker([0, 0], {radius: 6, color: '#111', fillOpacity: 0.9});
var estMarker = L.circleMarker([0, 0], {radius: 6, color: '#e0301e', fillOpacity: 0.9});
var errLine = L.polyline([[0, 0], [0, 0]], {color: '#e0301e', weight: 1});

function current() {
  return planners[Number(select.value) || 0];
}

function showFleetLegend(fleet) {
  fleet.vehicles.forEach(function(v) {
    var row = el('div', {'class': 'vehicle'});
    var swatch = el('span', {'class': 'swatch'});
    swatch.style.background = v.colour;
    row.appendChild(swatch);
    row.appendChild(el('span', {}, ' ' + v.id + ': ' + fmt(v.length_km, 2) + ' km'));
    legend.appendChild(row);
  });
}

function showLegend(q) {
  legend.textContent = '';
  if (q.p.fleet && toggles.route.checked && !toggles.weights.checked)
    return showFleetLegend(q.p.fleet);
  var lo, hi, what;
  if (toggles.drift.checked) {
    lo = fmt(q.drange[0], 2) + ' %';
    hi = fmt(q.drange[1], 2) + ' %';
    what = 'drift';
  } else if (toggles.weights.checked) {
    lo = fmt(wr[0], 2);
    hi = fmt(wr[1], 2);
    what = 'weight';
  } else {
    lo = '1x';
    hi = q.nmax + 'x';
    what = 'driven';
  }
  var bar = el('div', {'class': 'bar'});
  bar.style.background =
      'linear-gradient(to right,' + [0, 0.25, 0.5, 0.75, 1].map(ramp).join(',') + ')';
  legend.appendChild(el('span', {}, what + ' ' + lo));
  legend.appendChild(bar);
  legend.appendChild(el('span', {}, hi));
}

// The error chart: each curve {xs, err, colour} over x0..x1, a cursor at x, a caption below.
function errorChart(curves, x0, x1, x, caption) {
  var ctx = chart.getContext('2d'), W = chart.width, H = chart.height, m = 24, emax = 0;
  ctx.clearRect(0, 0, W, H);
  curves.forEach(function(c) {
    emax = Math.max(emax, range(c.err)[1]);
  });
  var px = function(v) {
    return m + ((v - x0) / Math.max(x1 - x0, 1e-9)) * (W - m - 4);
  };
  ctx.strokeStyle = '#999';
  ctx.strokeRect(m, 4, W - m - 4, H - m - 4);
  ctx.fillStyle = '#333';
  ctx.font = '10px sans-serif';
  ctx.fillText(fmt(emax, 2) + ' m', 2, 12);
  ctx.fillText('0', 2, H - m);
  ctx.fillText(caption, m + 4, H - 8);
  curves.forEach(function(c) {
    ctx.strokeStyle = c.colour;
    ctx.beginPath();
    c.xs.forEach(function(v, i) {
      var py = H - m - (c.err[i] / emax) * (H - m - 8);
      if (i === 0)
        ctx.moveTo(px(v), py);
      else
        ctx.lineTo(px(v), py);
    });
    ctx.stroke();
  });
  ctx.strokeStyle = '#1f3a5f';
  ctx.beginPath();
  ctx.moveTo(px(x), 4);
  ctx.lineTo(px(x), H - m);
  ctx.stroke();
}

function drawChart(q, at) {
  var d = q.p.drive;
  if (!d || d.d.length < 2) {
    var ctx = chart.getContext('2d');
    ctx.clearRect(0, 0, chart.width, chart.height);
    ctx.fillText('no evaluated drive', 24, chart.height / 2);
    return;
  }
  var dmax = d.d[d.d.length - 1] || 1;
  errorChart(
      [{xs: d.d, err: d.err, colour: '#e0301e'}], 0, dmax, d.d[at],
      'error vs distance, ' + fmt(dmax / 1000, 2) + ' km');
}

function moveTo(i) {
  var q = current(), d = q.p.drive;
  if (q.fleetDrives && q.fleetDrives.length) return moveFleetTo(q, i);
  if (!d || !d.gt.length) {
    readout.textContent = 'no evaluated drive';
    return;
  }
  i = Math.max(0, Math.min(d.gt.length - 1, i));
  gtMarker.setLatLng(d.gt[i]);
  estMarker.setLatLng(d.est[i]);
  errLine.setLatLngs([d.gt[i], d.est[i]]);
  readout.textContent = 't ' + fmt(d.t[i], 1) + ' s   driven ' + fmt(d.d[i] / 1000, 3) + ' km\n' +
      'trajectory error ' + fmt(d.err[i], 3) + ' m';
  drawChart(q, i);
}

// --- the fleet along the drive: the vehicles drive at once, so the slider is the shared
// simulation time and every vehicle is shown where it was then (at its end once it arrived).
var FLEET_STEPS = 2000;
function fleetTimes(q) {
  var lo = Infinity, hi = -Infinity;
  q.fleetDrives.forEach(function(f) {
    lo = Math.min(lo, f.v.drive.t[0]);
    hi = Math.max(hi, f.v.drive.t[f.v.drive.t.length - 1]);
  });
  return [lo, hi];
}
function fleetTimeAt(q, i) {
  var span = fleetTimes(q);
  return span[0] + (span[1] - span[0]) * i / (FLEET_STEPS - 1);
}
// The last pose of drive d at or before time t (its first before it starts).
function indexAtTime(d, t) {
  var lo = 0, hi = d.t.length - 1;
  while (lo < hi) {
    var mid = Math.ceil((lo + hi) / 2);
    if (d.t[mid] <= t)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}
function drawFleetChart(q, t) {
  var span = fleetTimes(q);
  errorChart(
      q.fleetDrives.map(function(f) {
        return {xs: f.v.drive.t, err: f.v.drive.err, colour: f.v.colour};
      }),
      span[0], span[1], t, 'error vs time, ' + fmt(span[1] - span[0], 0) + ' s');
}
function moveFleetTo(q, i) {
  var t = fleetTimeAt(q, Math.max(0, Math.min(FLEET_STEPS - 1, i)));
  var lines = ['t ' + fmt(t, 1) + ' s   (driven, trajectory error)'];
  q.fleetDrives.forEach(function(f) {
    var d = f.v.drive, k = indexAtTime(d, t);
    f.gt.setLatLng(d.gt[k]);
    f.est.setLatLng(d.est[k]);
    f.err.setLatLngs([d.gt[k], d.est[k]]);
    lines.push(f.v.id + ': ' + fmt(d.d[k] / 1000, 3) + ' km, error ' + fmt(d.err[k], 3) + ' m');
  });
  readout.textContent = lines.join('\n');
  drawFleetChart(q, t);
}
function fleetMarkers(q) {
  var out = [];
  (q.fleetDrives || []).forEach(function(f) {
    out.push(f.gt, f.est, f.err);
  });
  return out;
}

function showFleetSummary(fleet) {
  summary.appendChild(el('h2', {}, 'Fleet: ' + fleet.vehicles.length + ' vehicles'));
  summary.appendChild(
      el('div', {}, 'makespan (longest route): ' + fmt(fleet.makespan_km, 2) + ' km'));
  if (fleet.campaign) summary.appendChild(el('div', {}, fleet.campaign));
  summary.appendChild(el('div', {}, 'figures: the fleet tables below the map'));
  if (fleet.merged_map_png) {
    summary.appendChild(el('h2', {}, 'Merged map from above'));
    summary.appendChild(el('img', {
      id: 'fleet-map-error',
      src: fleet.merged_map_png,
      alt: 'the merged map of every vehicle coloured by its distance to the world surface',
      style: 'width:100%'
    }));
  }
}

function showSummary(q) {
  var m = q.p.metrics || {};
  summary.textContent = '';
  if (q.p.fleet) return showFleetSummary(q.p.fleet);
  summary.appendChild(el('h2', {}, q.p.name + ': SLAM'));
  [['ATE RMSE', fmt(m.ate_rmse_m, 3) + ' m'], ['ATE max', fmt(m.ate_max_m, 3) + ' m'],
   ['drift (RPE)', fmt(m.rpe_trans_pct, 2) + ' %'],
   ['map error, median', fmt(m.map_median_dist_m, 2) + ' m'],
   ['map error, aligned median', fmt(m.map_aligned_median_dist_m, 2) + ' m'],
   ['loop closures found', fmt(m.loop_closures, 0)]]
      .forEach(function(r) {
        summary.appendChild(el('div', {}, r[0] + ': ' + r[1]));
      });
  if (q.p.map_error_png) {
    summary.appendChild(el('h2', {}, 'Map error from above'));
    summary.appendChild(el('img', {
      id: 'map-error',
      src: q.p.map_error_png,
      alt: q.p.name + ': SLAM map coloured by its distance to the world surface',
      style: 'width:100%'
    }));
  }
}

function refresh() {
  var q = current();
  [[streets, 'streets'], [weights, 'weights']].forEach(function(l) {
    if (toggles[l[1]].checked)
      l[0].addTo(map);
    else
      map.removeLayer(l[0]);
  });
  planners.forEach(function(o) {
    ['route', 'drift', 'traj'].forEach(function(k) {
      if (o === q && toggles[k].checked)
        o[k].addTo(map);
      else
        map.removeLayer(o[k]);
    });
  });
  var fleet = q.fleetDrives && q.fleetDrives.length;
  var n = fleet ? FLEET_STEPS : q.p.drive ? q.p.drive.gt.length : 0;
  slider.max = String(Math.max(0, n - 1));
  [gtMarker, estMarker, errLine].forEach(function(l) {
    if (n && !fleet)
      l.addTo(map);
    else
      map.removeLayer(l);
  });
  planners.forEach(function(o) {
    fleetMarkers(o).forEach(function(l) {
      if (o === q && toggles.traj.checked)
        l.addTo(map);
      else
        map.removeLayer(l);
    });
  });
  showLegend(q);
  showSummary(q);
  moveTo(Number(slider.value));
}

select.addEventListener('change', function() {
  slider.value = '0';
  refresh();
});
Object.keys(toggles).forEach(function(k) {
  toggles[k].addEventListener('change', refresh);
});
slider.addEventListener('input', function() {
  moveTo(Number(slider.value));
});

// --- tables
data.tables.forEach(function(t) {
  tables.appendChild(el('h2', {}, t.title));
  var table = el('table');
  var tr = el('tr');
  t.head.forEach(function(h) {
    tr.appendChild(el('th', {}, h));
  });
  table.appendChild(tr);
  t.rows.forEach(function(r) {
    var row = el('tr');
    r.forEach(function(c) {
      row.appendChild(el('td', {}, String(c)));
    });
    table.appendChild(row);
  });
  tables.appendChild(table);
});

// report.html#NAME opens with that route chosen (#fleet: the fleet's).
var wanted = decodeURIComponent(location.hash.slice(1));
planners.forEach(function(q, i) {
  if (wanted && (q.p.name === wanted || (q.p.fleet && q.p.fleet.name === wanted)))
    select.value = String(i);
});

var bounds = streets.getBounds();
if (bounds.isValid())
  map.fitBounds(bounds, {padding: [10, 10]});
else
  map.setView([0, 0], 0);
refresh();

body.setAttribute('data-streets', String(streets.getLayers().length));
body.setAttribute('data-route-features', featureCounts.join(','));
body.setAttribute('data-fleet-features', fleetCounts.join(','));
body.setAttribute('data-fleet-drives', fleetDriveCounts.join(','));
body.setAttribute('data-status', 'ok');
document.title = document.title + ' (ready)';
})();
