// rpt report: draws the page from the inline JSON block #rpt-data (written by engine/report/report_data.cc).
// Plots with Chart.js, the 3D viewer with three.js (OrbitControls), the camera views on 2D canvases.
// For tests (tests/report/), body carries data-rpt-ready, data-rpt-plots, data-rpt-skeletons,
// data-rpt-gt-skeletons, data-rpt-nonblank-pixels and data-rpt-camera-views once the first frame is drawn.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('rpt-data').textContent);
  const body = document.body;
  // The tracks' colours as rpt render draws them (engine/track_palette.h, in the page's data).
  const PALETTE = data.track_palette && data.track_palette.length ? data.track_palette : ['#1f77b4'];
  const GT_COLOUR = '#b8c4cf', MISSED_COLOUR = '#ff2d2d', DETECTION_COLOUR = '#9aa3ad', CAMERA_COLOUR = '#7fa7d1';
  const trackColour = (id) => (id >= 0 ? PALETTE[id % PALETTE.length] : '#f58231');
  const fmt = (v, digits) => (v === null || v === undefined || Number.isNaN(v) ? '-' : Number(v).toFixed(digits));
  const el = (id) => document.getElementById(id);

  // ---- header, summary, warnings, run info ----
  el('title').textContent = data.title;
  const run = data.run || {};
  el('subtitle').textContent = [run.date_utc, run.git_revision && 'revision ' + run.git_revision, run.command]
      .filter(Boolean).join(' \u00b7 ');

  const ACCURACY = [['pcp', 'PCP', '%', 1], ['pck100', 'PCK@100', '%', 1], ['pck500', 'PCK@500', '%', 1],
                    ['mpjpe_mm', 'MPJPE', 'mm', 1], ['recall100', 'Recall@100', '%', 1],
                    ['recall500', 'Recall@500', '%', 1], ['invalid', 'Invalid', '%', 1], ['f1', 'F1', '%', 1]];
  // A run without ground truth (rpt triangulate) has no accuracy: its columns are left out.
  const COLUMNS = (data.evaluated === false ? [] : ACCURACY).concat([['fps', 'FPS', '1/s', 0], ['frames', 'Frames', '', 0]]);
  (function summary() {
    const table = el('summary-table');
    let html = '<thead><tr><th>run</th>' + COLUMNS.map((c) => `<th>${c[1]}${c[2] ? ' (' + c[2] + ')' : ''}</th>`).join('') + '</tr></thead><tbody>';
    const row = (label, values, cls) => `<tr class="${cls}"><td>${label}</td>` +
        COLUMNS.map((c) => `<td>${values[c[0]] === undefined ? '' : fmt(values[c[0]], c[3])}</td>`).join('') + '</tr>';
    html += row('this run (rpt)', data.summary || {}, 'ours');
    if (data.paper) html += row(data.paper.label, data.paper, 'paper');
    table.innerHTML = html + '</tbody>';
    el('summary-note').textContent = data.evaluated === false
        ? 'No ground truth (rpt triangulate): no accuracy metrics; ' + fmt((data.summary || {}).output_persons, 0) + ' persons triangulated.'
        : data.paper
        ? 'Paper row: Bermuth et al., CVPR 2026 (their 2D network and protocol, FPS on their machine; results/paper.json).'
        : 'The paper has no row for this dataset.';
    const legacy = (data.summary || {}).legacy_pcp;
    if (legacy !== undefined && legacy !== null) el('summary-note').textContent += ' Legacy PCP (actors 1-3): ' + fmt(legacy, 1) + ' %.';
    // Why the Invalid predictions are not matches (summary.json "invalid_causes", docs/diagnostics.md).
    const causes = (data.summary || {}).invalid_causes;
    if (causes && typeof causes === 'object') {
      const count = (key) => (typeof causes[key] === 'number' ? causes[key] : 0);
      const total = count('duplicate') + count('near_matched_gt') + count('near_missed_gt') + count('far_from_gt') + count('no_gt');
      if (total > 0) {
        el('summary-note').textContent += ' Unmatched predictions (Invalid): ' + total + ' = ' + count('duplicate') +
            ' duplicate, ' + count('near_matched_gt') + ' beside a found person, ' + count('near_missed_gt') +
            ' near a missed person, ' + count('far_from_gt') +
            ' far from every GT person, ' + count('no_gt') + ' without GT.';
      }
    }
    // PCP per part (summary.json "pcp_parts"); names are set as text, never as markup.
    const parts = (data.summary || {}).pcp_parts;
    if (parts && typeof parts === 'object' && Object.keys(parts).length) {
      const partsTable = el('pcp-parts-table');
      const head = partsTable.createTHead().insertRow();
      const values = partsTable.createTBody().insertRow();
      const th = document.createElement('th');
      th.textContent = 'PCP per part (%)';
      head.appendChild(th);
      values.insertCell().textContent = 'this run (rpt)';
      for (const [name, value] of Object.entries(parts)) {
        const cell = document.createElement('th');
        cell.textContent = name.replace(/_/g, ' ');
        head.appendChild(cell);
        values.insertCell().textContent = typeof value === 'number' ? fmt(value, 1) : '';
      }
      // With --loss-table: the same parts if only those beyond the best pair of the person's own
      // detections were wrong (summary.json "loss_table.parts.per_part", docs/diagnostics.md).
      const lossParts = ((data.summary || {}).loss_table || {}).parts;
      const perPart = lossParts && typeof lossParts.per_part === 'object' ? lossParts.per_part : null;
      if (perPart) {
        const reach = partsTable.tBodies[0].insertRow();
        reach.insertCell().textContent = 'best pair of the detections';
        for (const name of Object.keys(parts)) {
          const counts = perPart[name];
          const ok = counts && typeof counts.evaluated === 'number' && counts.evaluated > 0 &&
              typeof counts.beyond_best_pair === 'number';
          reach.insertCell().textContent = ok ? fmt(100 * (counts.evaluated - counts.beyond_best_pair) / counts.evaluated, 1) : '';
        }
      }
      partsTable.hidden = false;
    }
    // With --loss-table: where the GT persons are lost, and the joint references (docs/diagnostics.md).
    const losses = (data.summary || {}).loss_table;
    if (losses && typeof losses === 'object' && losses.categories && typeof losses.categories === 'object') {
      const c = losses.categories;
      const n = (key) => (typeof c[key] === 'number' ? c[key] : 0);
      el('summary-note').textContent += ' Where the ' + fmt(losses.gt_persons, 0) + ' GT persons are lost (--loss-table): ' +
          n('found') + ' found, ' + n('fewer_than_2_views') + ' detected in fewer than 2 views, ' + n('pair_filtered') +
          ' pair filtered, ' + n('grouped_wrongly') + ' grouped wrongly, ' + n('merged_wrongly') + ' merged wrongly, ' +
          n('rejected') + ' rejected, ' + n('placed_off') + ' placed off.';
      const r = losses.joint_references;
      if (r && typeof r.joints === 'number' && r.joints > 0) {
        el('summary-note').textContent += ' Mean joint error over ' + r.joints + ' joints: output ' + fmt(r.output_mm, 1) +
            ' mm, all views fitted ' + fmt(r.all_views_mm, 1) + ' mm, best pair per joint ' + fmt(r.best_pair_mm, 1) + ' mm.';
      }
    }
    const list = el('warnings');
    const warnings = (data.warnings || []).concat((data.summary || {}).warnings || []);
    for (const w of warnings) {
      const li = document.createElement('li');
      // Warnings are strings, or objects with a message (summary.json's {code, message}).
      li.textContent = typeof w === 'string' ? w : (w && typeof w.message === 'string' ? w.message : JSON.stringify(w));
      list.appendChild(li);
    }
  })();

  (function runInfo() {
    const rows = [['command', run.command], ['date (UTC)', run.date_utc], ['git revision', run.git_revision],
                  ['machine', (run.cpu || '') + (run.hardware_threads ? ', ' + run.hardware_threads + ' hardware threads' : '')],
                  ['threads', run.threads], ['build', (run.compiler || '') + ' ' + (run.build_type || '')],
                  ['input corrections', (run.input_warnings || []).join('; ') || 'none'],
                  ['frames with a 3D scene', data.scenes ? data.scenes.length + ' (at most ' + data.max_scene_frames + ', evenly spaced)' : 'none']];
    el('run-table').innerHTML = rows.map((r) => `<tr><th>${r[0]}</th><td></td></tr>`).join('');
    el('run-table').querySelectorAll('td').forEach((td, i) => { td.textContent = rows[i][1] === undefined ? '' : String(rows[i][1]); });
    el('config').textContent = JSON.stringify(data.config, null, 2);
  })();

  // ---- plots ----
  let plots = 0;
  Chart.defaults.animation = false;
  Chart.defaults.maintainAspectRatio = false;
  Chart.defaults.font.size = 11;
  function plot(id, config) {
    new Chart(el(id), config);
    plots += 1;
  }
  const joints = data.per_joint || [];
  // Plots that need ground truth are left out of a run without it (rpt triangulate).
  const hasGt = data.evaluated !== false;
  if (!hasGt) for (const id of ['plot-joints', 'plot-recall']) el(id).closest('figure').hidden = true;
  // Without ground truth nothing is invalid or missed, and no GT is drawn: those legend entries go.
  if (!hasGt) document.querySelectorAll('.legend .gt-only').forEach((node) => node.remove());
  if (hasGt) plot('plot-joints', {
    type: 'bar',
    data: { labels: joints.map((j) => j.joint),
            datasets: [{ label: 'mean error (mm)', data: joints.map((j) => j.mean_error_mm), backgroundColor: '#4f86c6' }] },
    options: { plugins: { legend: { display: false } }, scales: { y: { beginAtZero: true, title: { display: true, text: 'mm' } } } },
  });
  if (!hasGt) {
    el('plot-frames').closest('figure').querySelector('figcaption').firstChild.textContent =
        'Persons triangulated over frames (no ground truth) ';
  }
  const curve = data.recall_curve || { threshold_mm: [], recall: [] };
  // The plots computed from the re-loaded input have nothing to show without it: their captions say
  // so (a note appended: a caption may hold controls, e.g. the sequence selector).
  const noteCaption = (id, text) => {
    const note = document.createElement('span');
    note.className = 'caption-note';
    note.textContent = text;
    el(id).closest('figure').querySelector('figcaption').appendChild(note);
  };
  if (!data.input_loaded) {
    for (const id of ['plot-recall', 'plot-frames']) noteCaption(id, ': not available (the run\'s input could not be re-loaded)');
  }
  if (hasGt && !joints.some((j) => j.mean_error_mm !== null && j.mean_error_mm !== undefined)) {
    noteCaption('plot-joints', ': no matched person');
  }
  if (data.input_loaded && data.evaluated !== false && !curve.recall.length) {
    el('plot-recall').closest('figure').querySelector('figcaption').textContent +=
        ': not computed (the curve redoes the greedy matching; this run used metrics.matching = hungarian)';
  }
  const recallPoints = curve.threshold_mm.map((t, i) => ({ x: t, y: curve.recall[i] }));
  // The paper's two recall points, for reference.
  const paperPoints = data.paper ? [{ x: 100, y: data.paper.recall100 }, { x: 500, y: data.paper.recall500 }] : [];
  if (hasGt) plot('plot-recall', {
    type: 'scatter',
    data: { datasets: [{ label: 'this run', data: recallPoints, showLine: true, borderColor: '#2f6fb0', pointRadius: 0 }]
        .concat(data.paper ? [{ label: 'paper', data: paperPoints, pointRadius: 5, pointStyle: 'rectRot', backgroundColor: '#c0392b' }] : []) },
    // A margin past 500 mm and 100 % so that the paper's points are not cut by the plot's edge.
    options: { scales: { x: { min: 0, max: 520, title: { display: true, text: 'threshold (mm)' },
                              afterBuildTicks: (axis) => { axis.ticks = [0, 100, 200, 300, 400, 500].map((value) => ({ value })); } },
                         y: { min: 0, max: 104, title: { display: true, text: 'recall (%)' },
                              afterBuildTicks: (axis) => { axis.ticks = [0, 20, 40, 60, 80, 100].map((value) => ({ value })); } } } },
  });
  const steps = data.steps || [];
  plot('plot-step-times', {
    type: 'bar',
    data: { labels: steps.map((s) => s.step), datasets: [{ data: steps.map((s) => s.time_us_median), backgroundColor: '#6aa84f' }] },
    options: { indexAxis: 'y', plugins: { legend: { display: false } },
               scales: { x: { title: { display: true, text: 'us' } }, y: { ticks: { autoSkip: false, font: { size: 9 } } } } },
  });
  plot('plot-step-counts', {
    type: 'bar',
    data: { labels: steps.map((s) => s.step), datasets: [{ data: steps.map((s) => s.count_per_frame), backgroundColor: '#b07aa1' }] },
    options: { indexAxis: 'y', plugins: { legend: { display: false } },
               scales: { x: { title: { display: true, text: 'items per frame' } }, y: { ticks: { autoSkip: false, font: { size: 9 } } } } },
  });

  const sequences = data.sequences || [];
  const scenes = data.scenes || [];
  let framesChart = null;
  (function framePlot() {
    const select = el('frames-sequence');
    sequences.forEach((s, i) => {
      const option = document.createElement('option');
      option.value = i;
      option.textContent = s.name + ' (' + s.frame_ids.length + ' frames)';
      select.appendChild(option);
    });
    select.hidden = sequences.length < 2;
    const draw = (s) => {
      const seq = sequences[s];
      if (!seq) return;
      const points = seq.mpjpe_mm.map((v, f) => ({ x: f, y: v }));
      const invalid = seq.num_invalid.map((v, f) => ({ x: f, y: v }));
      const missed = seq.num_gt.map((v, f) => ({ x: f, y: v - seq.num_matched[f] }));
      // Counts of persons: whole-number ticks, and room above the highest so that its line does not
      // lie on the plot's border.
      const counts = data.evaluated === false ? seq.num_predictions : invalid.map((p) => p.y).concat(missed.map((p) => p.y));
      const countMax = counts.reduce((a, b) => Math.max(a, b), 1) + 1;  // no spread: a long run has many frames
      if (framesChart) framesChart.destroy();
      framesChart = new Chart(el('plot-frames'), {
        type: 'scatter',
        data: { datasets: (data.evaluated === false ? [
          // No ground truth: the persons triangulated per frame instead of errors.
          { label: 'persons triangulated', data: seq.num_predictions.map((v, f) => ({ x: f, y: v })), showLine: true, stepped: true, borderColor: '#2f6fb0', backgroundColor: '#2f6fb0', pointRadius: 0, borderWidth: 1, yAxisID: 'count' },
        ] : [
          { label: 'MPJPE (mm)', data: points, showLine: true, borderColor: '#2f6fb0', backgroundColor: '#2f6fb0', pointRadius: 1.5, borderWidth: 1, yAxisID: 'y', spanGaps: false },
          { label: 'missed GT', data: missed, showLine: true, stepped: true, borderColor: '#ff2d2d', backgroundColor: '#ff2d2d', pointRadius: 0, borderWidth: 1, yAxisID: 'count' },
          { label: 'invalid predictions', data: invalid, showLine: true, stepped: true, borderColor: '#f58231', backgroundColor: '#f58231', pointRadius: 0, borderWidth: 1, yAxisID: 'count' },
        ]).concat([
          { label: 'selected frame', data: [], pointRadius: 6, pointStyle: 'triangle', backgroundColor: '#000', yAxisID: data.evaluated === false ? 'count' : 'y' },
        ]) },
        options: {
          scales: { x: { title: { display: true, text: 'frame' }, ticks: { precision: 0 } },
                    y: { display: data.evaluated !== false, beginAtZero: true, title: { display: true, text: 'mm' } },
                    count: { position: 'right', beginAtZero: true, max: countMax, ticks: { precision: 0 },
                             grid: { drawOnChartArea: data.evaluated === false }, title: { display: true, text: 'persons' } } },
          onClick: (event) => {
            const hits = framesChart.getElementsAtEventForMode(event, 'nearest', { axis: 'x', intersect: false }, true);
            if (hits.length) openFrame(s, hits[0].index);
          },
        },
      });
      framesChart.rptSequence = s;
    };
    select.addEventListener('change', () => { draw(Number(select.value)); markFrame(); });
    if (sequences.length) { draw(0); plots += 1; }
  })();

  // ---- frame selection ----
  const slider = el('frame-slider');
  slider.max = Math.max(0, scenes.length - 1);
  let current = 0;
  function openFrame(s, f) {
    // The nearest frame that carries a scene (all of them unless the run was sampled).
    let best = -1, bestDistance = Infinity;
    scenes.forEach((scene, i) => {
      if (scene.sequence !== s) return;
      const d = Math.abs(scene.frame - f);
      if (d < bestDistance) { best = i; bestDistance = d; }
    });
    if (best >= 0) showScene(best);
    el('viewer').scrollIntoView({ behavior: 'auto' });
  }
  function markFrame() {
    if (!framesChart || !scenes.length) return;
    const scene = scenes[current];
    // The last series marks the frame shown: on the MPJPE (mm) axis with ground truth, else on
    // the persons-triangulated (count) axis.
    const datasets = framesChart.data.datasets;
    const set = datasets[datasets.length - 1];
    const seq = sequences[scene.sequence];
    const series = data.evaluated === false ? seq.num_predictions : seq.mpjpe_mm;
    const y = series && series[scene.frame] !== null && series[scene.frame] !== undefined ? series[scene.frame] : 0;
    set.data = scene.sequence === framesChart.rptSequence ? [{ x: scene.frame, y: y }] : [];
    framesChart.update('none');
  }
  el('prev').addEventListener('click', () => showScene(Math.max(0, current - 1)));
  el('next').addEventListener('click', () => showScene(Math.min(scenes.length - 1, current + 1)));
  slider.addEventListener('input', () => showScene(Number(slider.value)));
  let timer = null;
  el('play').addEventListener('click', () => {
    if (timer) { clearInterval(timer); timer = null; el('play').innerHTML = '&#9654;'; return; }
    el('play').innerHTML = '&#10074;&#10074;';
    timer = setInterval(() => showScene((current + 1) % Math.max(1, scenes.length)), 200);
  });

  // ---- 3D viewer ----
  const view = el('view3d');
  let renderer = null, scene3d = null, camera3d = null, controls = null, frameGroup = null, cameraGroup = null, cameraSequence = -1;
  const upOf = (s) => new THREE.Vector3().fromArray((sequences[s] && sequences[s].up) || [0, 0, 1]);
  function initViewer() {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(view.clientWidth, view.clientHeight);
    renderer.setClearColor(0x10161d);
    view.appendChild(renderer.domElement);
    scene3d = new THREE.Scene();
    camera3d = new THREE.PerspectiveCamera(45, view.clientWidth / view.clientHeight, 0.05, 500);
    controls = new THREE.OrbitControls(camera3d, renderer.domElement);
    controls.addEventListener('change', render);
    controls.addEventListener('start', () => { userMoved = true; });
    window.addEventListener('resize', () => {
      renderer.setSize(view.clientWidth, view.clientHeight);
      camera3d.aspect = view.clientWidth / view.clientHeight;
      camera3d.updateProjectionMatrix();
      render();
    });
  }
  function render() { if (renderer) renderer.render(scene3d, camera3d); }
  // Until the user drags or zooms, each frame is shown with all its persons in view: the view of the
  // sequence is moved back (never closer) while a joint lies outside it (a person far from the
  // others opened an empty view, MVOR). At most 20 steps of 25 %: an outlier miles off stays out.
  let userMoved = false;
  function keepPersonsInView(sc) {
    if (userMoved || !camera3d) return;
    const points = [];
    for (const person of sc.gt.concat(sc.predictions)) {
      for (const p of person.joints) if (p) points.push(new THREE.Vector3().fromArray(p));
    }
    const inView = (v) => {
      const q = v.clone().project(camera3d);
      return Math.abs(q.x) <= 0.95 && Math.abs(q.y) <= 0.95 && q.z > -1 && q.z < 1;
    };
    camera3d.updateMatrixWorld();
    for (let step = 0; step < 20 && !points.every(inView); ++step) {
      const offset = camera3d.position.clone().sub(controls.target).multiplyScalar(1.25);  // before position changes
      camera3d.position.copy(controls.target).add(offset);
      camera3d.updateMatrixWorld();
    }
    controls.update();
  }

  function segmentsGeometry(points, edges) {
    const positions = [];
    for (const [a, b] of edges) {
      if (points[a] && points[b]) positions.push(...points[a], ...points[b]);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    return geometry;
  }
  function pointsGeometry(points) {
    const positions = [];
    for (const p of points) if (p) positions.push(...p);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    return geometry;
  }
  function skeleton(points, edges, colour, dashed, size) {
    const group = new THREE.Group();
    const material = dashed ? new THREE.LineDashedMaterial({ color: colour, dashSize: 0.05, gapSize: 0.04 })
                            : new THREE.LineBasicMaterial({ color: colour });
    const lines = new THREE.LineSegments(segmentsGeometry(points, edges), material);
    if (dashed) lines.computeLineDistances();
    group.add(lines);
    group.add(new THREE.Points(pointsGeometry(points), new THREE.PointsMaterial({ color: colour, size: size, sizeAttenuation: true })));
    return group;
  }
  function dispose(group) {
    if (!group) return;
    group.traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
    scene3d.remove(group);
  }
  function placeCameras(s) {
    dispose(cameraGroup);
    cameraGroup = new THREE.Group();
    const seq = sequences[s];
    const material = new THREE.LineBasicMaterial({ color: CAMERA_COLOUR });
    const centers = [];
    for (const cam of seq.cameras) {
      // A camera too far away to draw (rpt report leaves out its position) is only listed.
      if (!cam.center || !cam.corners) continue;
      const c = cam.center, k = cam.corners, positions = [];
      for (let i = 0; i < 4; i++) positions.push(...c, ...k[i], ...k[i], ...k[(i + 1) % 4]);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
      cameraGroup.add(new THREE.LineSegments(geometry, material));
      centers.push(new THREE.Vector3().fromArray(c));
    }
    // Floor grid through the lowest GT or predicted joint of the sequence's scenes, normal to the up direction.
    const up = upOf(s);
    const target = new THREE.Vector3();
    let count = 0, floor = Infinity;
    for (const sc of scenes) {
      if (sc.sequence !== s) continue;
      for (const person of sc.gt.concat(sc.predictions)) {
        for (const p of person.joints) {
          if (!p) continue;
          const v = new THREE.Vector3().fromArray(p);
          target.add(v); count += 1; floor = Math.min(floor, v.dot(up));
        }
      }
    }
    const cameraMean = centers.reduce((a, b) => a.add(b), new THREE.Vector3()).multiplyScalar(1 / Math.max(1, centers.length));
    if (count) target.multiplyScalar(1 / count); else target.copy(cameraMean);
    if (!Number.isFinite(floor)) floor = target.dot(up) - 1;
    const spread = centers.reduce((m, c) => Math.max(m, c.distanceTo(target)), 2);
    // At most 200 grid lines per side, however far the cameras are.
    const gridSize = Math.ceil(spread * 2);
    const grid = new THREE.GridHelper(gridSize, Math.min(gridSize, 200), 0x3a4654, 0x26303b);
    grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
    grid.position.copy(target.clone().sub(up.clone().multiplyScalar(target.dot(up) - floor)));
    cameraGroup.add(grid);
    scene3d.add(cameraGroup);
    camera3d.up.copy(up);
    const away = cameraMean.clone().sub(target);
    away.sub(up.clone().multiplyScalar(away.dot(up)));
    if (away.length() < 1e-3) away.set(1, 0, 0).sub(up.clone().multiplyScalar(up.x));
    // Close enough that the people fill the view; the cameras may lie outside it (zoom out to see them).
    let peopleRadius = 1;
    for (const sc of scenes) {
      if (sc.sequence !== s) continue;
      for (const person of sc.gt.concat(sc.predictions)) {
        for (const p of person.joints) if (p) peopleRadius = Math.max(peopleRadius, new THREE.Vector3().fromArray(p).distanceTo(target));
      }
    }
    const distance = Math.min(spread * 1.1, Math.max(3, peopleRadius * 2.2));
    away.setLength(distance);
    camera3d.position.copy(target).add(away).add(up.clone().multiplyScalar(distance * 0.7));
    controls.target.copy(target);
    controls.update();
    cameraSequence = s;
  }

  // ---- camera views ----
  const cameraCanvases = [];
  function cameraViews(s) {
    const box = el('cameras');
    box.innerHTML = '';
    cameraCanvases.length = 0;
    for (const cam of sequences[s].cameras) {
      const figure = document.createElement('figure');
      const caption = document.createElement('figcaption');
      const canvas = document.createElement('canvas');
      const scale = Math.min(1, 720 / Math.max(1, cam.width));
      canvas.width = Math.max(1, Math.round(cam.width * scale));
      canvas.height = Math.max(1, Math.round(cam.height * scale));
      canvas.rptScale = scale;
      figure.appendChild(caption);
      figure.appendChild(canvas);
      box.appendChild(figure);
      cameraCanvases.push({ canvas, caption, cam });
    }
  }
  function drawPerson2D(ctx, uv, edges, colour, scale, width, dashed) {
    ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = width;
    ctx.setLineDash(dashed ? [5, 4] : []);
    ctx.beginPath();
    for (const [a, b] of edges) {
      if (!uv[a] || !uv[b]) continue;
      ctx.moveTo(uv[a][0] * scale, uv[a][1] * scale);
      ctx.lineTo(uv[b][0] * scale, uv[b][1] * scale);
    }
    ctx.stroke();
    ctx.setLineDash([]);
    for (const p of uv) {
      if (!p) continue;
      ctx.beginPath(); ctx.arc(p[0] * scale, p[1] * scale, width + 0.8, 0, 2 * Math.PI); ctx.fill();
    }
  }
  function drawViews(sc) {
    const seq = sequences[sc.sequence];
    let drawn = 0;
    cameraCanvases.forEach(({ canvas, caption, cam }, c) => {
      const ctx = canvas.getContext('2d');
      const scale = canvas.rptScale;
      ctx.fillStyle = '#1b2129'; ctx.fillRect(0, 0, canvas.width, canvas.height);
      const v = sc.views[c] || { detections: [], predictions: [], gt: [] };
      for (const gt of v.gt) drawPerson2D(ctx, gt, seq.gt_edges, GT_COLOUR, scale, 1, true);
      for (const det of v.detections) drawPerson2D(ctx, det, seq.detection_edges, DETECTION_COLOUR, scale, 1.5, false);
      const labels = [];  // {x, y (baseline), w} of the labels drawn on this canvas
      v.predictions.forEach((p, i) => {
        const person = sc.predictions[i];
        drawPerson2D(ctx, p.uv, data.prediction_edges, trackColour(p.track_id), scale, 2, person && person.invalid);
        if (p.mean_error_px !== null) {
          const anchor = p.uv.find((q) => q);
          if (anchor) {
            // 12 px as shown: the canvas is drawn at up to 720 px and shrunk into its card.
            const fontPx = Math.max(12, Math.round(12 * canvas.width / Math.max(1, canvas.clientWidth || canvas.width)));
            ctx.font = fontPx + 'px system-ui, sans-serif'; ctx.fillStyle = '#fff';
            // Moved up (at most 6 lines) clear of the labels already drawn, as rpt render does.
            const text = fmt(p.mean_error_px, 1) + ' px', width = ctx.measureText(text).width;
            const x = anchor[0] * scale + 6;
            let y = anchor[1] * scale - 6;
            const hits = (yy) => labels.some((r) => x < r.x + r.w && r.x < x + width && yy - fontPx < r.y && r.y - fontPx < yy);
            for (let tries = 0; tries < 6 && hits(y); ++tries) y -= fontPx + 2;
            labels.push({ x, y, w: width });
            ctx.fillText(text, x, y);
          }
        }
      });
      // The mean over the view's measured joints, as rpt render's legend (not a mean of the persons' means).
      caption.textContent = `${cam.name} (${cam.width}x${cam.height}): ${v.detections.length} detection(s), ` +
          `${v.predictions.filter((p) => p.detection >= 0).length} of ${v.predictions.length} prediction(s) matched, ` +
          (v.error_joints > 0 ? `reprojection error ${fmt(v.mean_error_px, 1)} px (mean, ${v.error_joints} joints)`
                              : 'no joint matched a detection');
      drawn += 1;
    });
    return drawn;
  }

  // ---- one frame ----
  function countNonBlank() {
    const gl = renderer.getContext();
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const pixels = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    let count = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      if (Math.abs(pixels[i] - 0x10) + Math.abs(pixels[i + 1] - 0x16) + Math.abs(pixels[i + 2] - 0x1d) > 24) count += 1;
    }
    return count;
  }
  function showScene(i) {
    if (!scenes.length) return;
    current = i;
    slider.value = i;
    const sc = scenes[i];
    const seq = sequences[sc.sequence];
    if (cameraSequence !== sc.sequence) { placeCameras(sc.sequence); cameraViews(sc.sequence); }
    dispose(frameGroup);
    frameGroup = new THREE.Group();
    let skeletons = 0, gtSkeletons = 0;
    for (const g of sc.gt) {
      if (g.state < 0) continue;
      frameGroup.add(skeleton(g.joints, seq.gt_edges, g.state === 1 ? GT_COLOUR : MISSED_COLOUR, false, g.state === 1 ? 0.04 : 0.08));
      gtSkeletons += 1;
    }
    for (const p of sc.predictions) {
      frameGroup.add(skeleton(p.joints, data.prediction_edges, trackColour(p.track_id), p.invalid, 0.06));
      skeletons += 1;
    }
    scene3d.add(frameGroup);
    keepPersonsInView(sc);
    render();
    const matched = sc.gt.filter((g) => g.state === 1).length, kept = sc.gt.filter((g) => g.state >= 0).length;
    const invalid = sc.predictions.filter((p) => p.invalid).length;
    const frameError = seq.mpjpe_mm[sc.frame];
    el('frame-label').textContent = `${seq.name} \u00b7 frame ${sc.frame + 1}/${seq.frame_ids.length} \u00b7 ${sc.id}`;
    el('frame-stats').textContent = (data.evaluated === false
        ? `${sc.predictions.length} person(s) triangulated (no ground truth)`
        : `${sc.predictions.length} prediction(s), ${invalid} invalid; ${kept} GT person(s), ` +
          `${kept - matched} missed; frame MPJPE ${fmt(frameError, 1)} mm`) +
        (scenes.length < totalFrames() ? ` (the report carries ${scenes.length} of ${totalFrames()} frames, evenly spaced)` : '');
    const views = drawViews(sc);
    markFrame();
    body.dataset.rptSkeletons = String(skeletons);
    body.dataset.rptGtSkeletons = String(gtSkeletons);
    body.dataset.rptCameraViews = String(views);
    body.dataset.rptNonblankPixels = String(countNonBlank());
    body.dataset.rptFrame = sc.id;
  }
  const totalFrames = () => sequences.reduce((n, s) => n + s.frame_ids.length, 0);

  body.dataset.rptPlots = String(plots);
  if (!data.input_loaded || !scenes.length) {
    el('viewer').querySelector('h2').textContent = 'Frames: not available';
    el('view3d').hidden = true;
    // No frames: the slider, the play buttons and the legends go too.
    for (const node of el('viewer').querySelectorAll('.controls, .legend, #cameras, h3')) node.style.display = 'none';
    el('frame-stats').textContent = 'The run\'s input could not be re-loaded, so the report has no frames (see the warnings above).';
  } else {
    initViewer();
    // ?scene=K opens the K-th frame that carries a scene (0-based) instead of the first.
    const wanted = Number(new URLSearchParams(window.location.search).get('scene'));
    showScene(Number.isInteger(wanted) && wanted >= 0 && wanted < scenes.length ? wanted : 0);
  }
  // #only-<section>[+<section>...]: those sections alone (for screenshots of one part, docs/report.md).
  const only = /^#only-([\w+-]+)$/.exec(window.location.hash);
  if (only) {
    const shown = only[1].split('+');
    document.querySelectorAll('main > section').forEach((section) => { section.hidden = !shown.includes(section.id); });
    window.scrollTo(0, 0);
  }
  body.dataset.rptReady = '1';
})();
