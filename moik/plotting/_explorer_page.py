"""The explorer's page: HTML skeleton, style and the script that links fronts to postures.

:func:`page` assembles one self-contained HTML file: plotly.js inline once (from the
installed plotly package, nothing fetched), the panels' figures and posture data
as one JSON block, and :data:`SCRIPT`, which draws every figure and, when a point
of a front is clicked, draws that member's posture in 3-D (links through the
frame origins, the joints numbered, every joint frame's axes, the target and its
frame, the scene's obstacles, the arm's collision shapes placed by that posture's frames)
and lists its joint values and errors. The script
exposes ``window.moikExplorer`` (``select(panel, curve, index)``, ``state``) and
sets ``document.body.dataset.ready`` once every figure is drawn, for the tests.
"""

from __future__ import annotations

import html
import json

STYLE = """
body { font-family: system-ui, sans-serif; margin: 1.2em; color: #222; }
h1 { font-size: 1.45em; margin-bottom: 0.2em; }
h2 { font-size: 1.15em; border-bottom: 1px solid #ccc; margin-top: 1.6em; }
.notes { color: #555; font-size: 0.9em; }
.row { display: flex; flex-wrap: wrap; gap: 1em; }
.front, .curves { flex: 1 1 520px; min-width: 420px; height: 480px; }
.posture { flex: 1 1 480px; min-width: 420px; height: 480px; }
.details { font-size: 0.88em; margin-top: 0.4em; }
.details table, table.stats { border-collapse: collapse; margin: 0.3em 0 0.8em 0; }
.details td, .details th, table.stats td, table.stats th {
  border: 1px solid #ddd; padding: 2px 7px; text-align: right; }
.details th, table.stats th { background: #f3f3f3; }
td.name, th.name { text-align: left; }
.outside { color: #b00; font-weight: bold; }
.tables { overflow-x: auto; }
"""

SCRIPT = r"""
(function () {
  const DATA = JSON.parse(document.getElementById('moik-data').textContent);
  const AXIS = ['#d62728', '#2ca02c', '#1f77b4'];
  const state = {};
  const fmt = (v, d) => (v === null || v === undefined) ? '-' : Number(v).toPrecision(d || 4);
  const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({'&': '&amp;', '<': '&lt;',
    '>': '&gt;', '"': '&quot;'}[c]));

  function axes(origins, R, len, dash, name) {
    const out = [];
    for (let k = 0; k < 3; k++) {
      const x = [], y = [], z = [];
      for (let f = 0; f < origins.length; f++) {
        const o = origins[f], r = R[f];
        x.push(o[0], o[0] + len * r[0][k], null);
        y.push(o[1], o[1] + len * r[1][k], null);
        z.push(o[2], o[2] + len * r[2][k], null);
      }
      out.push({type: 'scatter3d', mode: 'lines', x: x, y: y, z: z, hoverinfo: 'skip',
                name: name + ' ' + 'xyz'[k], showlegend: false,
                line: {color: AXIS[k], width: dash ? 3 : 4, dash: dash ? 'dash' : 'solid'}});
    }
    return out;
  }

  function shapes(panel, P, i) {  // each body's mesh moved by this posture's frame
    return (panel.robot_shapes || []).map((s) => {
      const R = P.rotations[i][s.frame], o = P.origins[i][s.frame];
      const w = [[], [], []];
      for (let v = 0; v < s.x.length; v++) {
        for (let r = 0; r < 3; r++) {
          w[r].push(o[r] + R[r][0] * s.x[v] + R[r][1] * s.y[v] + R[r][2] * s.z[v]);
        }
      }
      return {type: 'mesh3d', name: s.name, x: w[0], y: w[1], z: w[2], i: s.i, j: s.j,
              k: s.k, color: '#1f77b4', opacity: 0.3, hoverinfo: 'name', showlegend: false,
              flatshading: true};
    });
  }

  function postureTraces(panel, P, i) {
    const o = P.origins[i], col = (k) => o.map((p) => p[k]);
    const J = P.joints[i], len = 0.08 * panel.scale;
    const traces = [
      {type: 'scatter3d', mode: 'lines+markers', name: 'links', x: col(0), y: col(1),
       z: col(2), line: {color: '#444', width: 7}, marker: {size: 3, color: '#444'},
       hovertemplate: 'frame %{pointNumber}<br>(%{x:.4g}, %{y:.4g}, %{z:.4g})<extra></extra>'},
      {type: 'scatter3d', mode: 'markers+text', name: 'joints', x: J.map((p) => p[0]),
       y: J.map((p) => p[1]), z: J.map((p) => p[2]), text: P.joint_labels[i],
       textposition: 'top right', marker: {size: 5, color: '#ff7f0e'},
       customdata: J.map((p, j) => j + 1), hovertemplate: 'joint %{customdata}<extra></extra>'},
      {type: 'scatter3d', mode: 'markers', name: 'base', x: [o[0][0]], y: [o[0][1]],
       z: [o[0][2]], marker: {size: 7, symbol: 'square', color: 'black'},
       hoverinfo: 'name'},
    ].concat(axes(o, P.rotations[i], len, false, 'frame'));
    const t = panel.target;
    if (t) {
      traces.push({type: 'scatter3d', mode: 'markers', name: 'target', x: [t.position[0]],
                   y: [t.position[1]], z: [t.position[2]],
                   marker: {size: 7, symbol: 'diamond', color: 'red'}, hoverinfo: 'name'});
      if (t.rotation) traces.push(...axes([t.position], [t.rotation], 1.5 * len, true, 'target'));
    }
    return traces.concat(panel.obstacles || [], shapes(panel, P, i));
  }

  function details(panel, ti, i) {
    const P = panel.postures[ti], tr = panel.traces[ti];
    let h = '<b>' + esc(tr.name) + '</b>, member ' + (i + 1) + ' of ' + tr.size + '<table><tr>';
    panel.objectives.forEach((n) => { h += '<th>' + esc(n) + '</th>'; });
    h += '</tr><tr>' + tr.F[i].map((v) => '<td>' + fmt(v) + '</td>').join('') + '</tr></table>';
    if (P.position_error) {
      h += 'position error ' + Number(P.position_error[i]).toExponential(3) + ' ' +
           esc(panel.unit);
      if (P.orientation_error) h += ', orientation error (geodesic) ' +
           Number(P.orientation_error[i]).toExponential(3) + ' rad';
      h += ' (forward kinematics of this member)';
    }
    h += '<table class="joints"><tr><th class="name">joint</th><th>value</th><th>deg</th>' +
         '<th>lower limit</th><th>upper limit</th></tr>';
    P.q[i].forEach((q, j) => {
      const lo = panel.limits[0][j], hi = panel.limits[1][j], pr = panel.prismatic[j];
      const bad = q < lo || q > hi ? ' class="outside"' : '';
      const unit = pr ? ' ' + esc(panel.unit) : ' rad';  // limits in the value's unit
      const limit = (v) => fmt(v) + unit + (pr ? '' : ' (' + fmt(v * 180 / Math.PI, 5) +
                                                      ' deg)');
      h += '<tr' + bad + '><td class="name">' + esc(panel.joint_names[j]) + '</td><td>' +
           fmt(q, 6) + unit + '</td><td>' + (pr ? '-' : fmt(q * 180 / Math.PI, 5)) +
           '</td><td>' + limit(lo) + '</td><td>' + limit(hi) + '</td></tr>';
    });
    return h + '</table>';
  }

  function select(p, ti, i) {
    const panel = DATA.panels[p];
    if (panel.kind !== 'front' || !panel.traces[ti] || i < 0 || i >= panel.traces[ti].size) {
      return false;
    }
    const box = document.getElementById('details-' + p);
    state[p] = {trace: ti, index: i};
    const fig = document.getElementById('front-' + p), tr = panel.traces[ti];
    Plotly.restyle(fig, {x: [[tr.F[i][0]]], y: [[tr.F[i][1]]]}, [panel.traces.length]);
    if (!panel.postures || !panel.postures[ti]) {
      box.innerHTML = '<b>' + esc(tr.name) + '</b>, member ' + (i + 1) + ': ' +
        esc(panel.no_posture || 'no posture for this front');
      return true;
    }
    const layout = Object.assign({}, panel.scene_layout, {uirevision: 'keep'});
    Plotly.react(document.getElementById('posture-' + p),
                 postureTraces(panel, panel.postures[ti], i), layout, {responsive: true});
    box.innerHTML = details(panel, ti, i);
    return true;
  }

  const draws = [];
  DATA.panels.forEach((panel, p) => {
    if (!panel.figure) return;
    const div = document.getElementById((panel.kind === 'front' ? 'front-' : 'figure-') + p);
    draws.push(Plotly.newPlot(div, panel.figure.data, panel.figure.layout,
                              {responsive: true}).then(() => {
      if (panel.kind !== 'front') return;
      div.on('plotly_click', (ev) => {
        const pt = ev.points[0];
        if (pt.curveNumber < panel.traces.length) select(p, pt.curveNumber, pt.pointNumber);
      });
      if (panel.initial) select(p, panel.initial[0], panel.initial[1]);
    }));
  });
  window.moikExplorer = {select: select, state: state, data: DATA};
  Promise.all(draws).then(() => { document.body.dataset.ready = '1'; });
})();
"""


def _json(data) -> str:
    """JSON safe inside a ``<script>`` element."""
    text = json.dumps(data, allow_nan=False, separators=(",", ":"))
    return text.replace("</", "<\\/")


def page(*, title: str, notes: list[str], panels: list[dict], plotlyjs: str) -> str:
    """The HTML of the explorer: ``panels`` as built by :mod:`moik.plotting.explorer`."""
    body = [f"<h1>{html.escape(title)}</h1>"]
    body += [f'<p class="notes">{html.escape(n)}</p>' for n in notes]
    for p, panel in enumerate(panels):
        body.append(f'<section class="panel panel-{panel["kind"]}" id="panel-{p}">'
                    f'<h2>{html.escape(panel["title"])}</h2>')
        if panel["kind"] == "front":
            posture = ('<div class="posture" id="posture-{0}"></div>' if panel["postures"]
                       else "")
            body.append(f'<div class="row"><div class="front" id="front-{p}"></div>'
                        + posture.format(p) + "</div>"
                        f'<div class="details" id="details-{p}">Click a point of a front to '
                        "see its posture.</div>")
        elif panel["kind"] == "curves":
            body.append(f'<div class="curves" id="figure-{p}"></div>')
        else:
            body.append('<div class="tables">' + table_html(panel["header"], panel["rows"])
                        + "</div>")
        body += [f'<p class="notes">{html.escape(n)}</p>' for n in panel.get("notes", [])]
        body.append("</section>")
    data = {"panels": [{k: v for k, v in pl.items() if k not in ("rows", "header")}
                       for pl in panels]}
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{html.escape(title)}</title><style>{STYLE}</style>"
            f'<script type="text/javascript">{plotlyjs}</script></head><body>'
            + "\n".join(body)
            + f'<script type="application/json" id="moik-data">{_json(data)}</script>'
            + f"<script>{SCRIPT}</script></body></html>\n")


def table_html(header: list[str], rows: list[list[str]]) -> str:
    """A statistics table (cells already formatted, as the report prints them)."""
    head = "".join(f'<th class="name">{html.escape(h)}</th>' if i == 0 else
                   f"<th>{html.escape(h)}</th>" for i, h in enumerate(header))
    lines = [f'<table class="stats"><tr>{head}</tr>']
    for row in rows:
        lines.append("<tr>" + "".join(f'<td class="name">{html.escape(c)}</td>' if i == 0
                                      else f"<td>{html.escape(c)}</td>"
                                      for i, c in enumerate(row)) + "</tr>")
    return "\n".join(lines) + "</table>"
