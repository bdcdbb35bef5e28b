#!/usr/bin/env python3
"""Compare proxy traces (proxy.py JSON lines) of a UT Austin Villa agent on two SimSpark servers.
usage: compare.py REF.jsonl TURF.jsonl [--csv-dir DIR] [--window SECONDS]
Walking phase = from the first perception whose play mode (GS pm) is not BeforeKickOff, for --window s of
perceived sim time (default: all).  Per perception cycle k: time, GS pm, GYR, ACC, HJ (deg), FRP lf/rf force;
commands = the hinge-effector velocities (rad/s) the agent sent after perception k (cyc k in the trace).
With --csv-dir the parsed per-cycle tables are written as CSV (one per trace) for cycle-by-cycle comparison.
"""
import json, math, re, sys, os, statistics as st

LEG = [f'{s}lj{i}' for s in 'lr' for i in range(1, 7)]
TOK = re.compile(r'\(|\)|[^\s()]+')


def sexp(s):
    out, stack = [], []
    cur = out
    for t in TOK.findall(s):
        if t == '(':
            stack.append(cur); n = []; cur.append(n); cur = n
        elif t == ')':
            cur = stack.pop() if stack else out
        else:
            cur.append(t)
    return out


def fl(x):
    try:
        return float(x)
    except ValueError:
        return float('nan')


def parse_perc(msg):
    d = {'hj': {}, 'frp': {}}
    for e in sexp(msg):
        if not isinstance(e, list) or not e:
            continue
        h = e[0]
        kv = {x[0]: x[1:] for x in e[1:] if isinstance(x, list) and x}
        if h == 'time':
            d['t'] = fl(kv['now'][0])
        elif h == 'GS':
            if 'pm' in kv: d['pm'] = kv['pm'][0]
            if 't' in kv: d['gt'] = fl(kv['t'][0])
        elif h == 'GYR':
            d['gyr'] = [fl(v) for v in kv['rt']]
        elif h == 'ACC':
            d['acc'] = [fl(v) for v in kv['a']]
        elif h == 'HJ':
            d['hj'][kv['n'][0]] = fl(kv['ax'][0])
        elif h == 'FRP':
            d['frp'][kv['n'][0]] = ([fl(v) for v in kv['c']], [fl(v) for v in kv['f']])
    return d


def parse_cmd(msg):
    c = {}
    for e in sexp(msg):
        if isinstance(e, list) and len(e) == 2 and not isinstance(e[1], list) and re.match(r'^[a-z]+e\d+$', e[0]):
            c[e[0]] = fl(e[1])
    return c


def load(path):
    percs, cmds = [], {}
    for line in open(path):
        r = json.loads(line)
        if r['dir'] == 's2a':
            p = parse_perc(r['msg']); p['cyc'] = r['cyc']; percs.append(p)
        else:
            c = parse_cmd(r['msg'])
            if c:
                cmds.setdefault(r['cyc'], {}).update(c)
    return percs, cmds


def eff(j):  # perceptor name -> effector name: llj3 -> lle3, hj1 -> he1, laj2 -> lae2
    return j.replace('j', 'e', 1) if j != 'hj1' and j != 'hj2' else 'he' + j[2]


def stats(xs):
    xs = [x for x in xs if x == x]
    if not xs:
        return (float('nan'),) * 4
    return (st.fmean(xs), st.pstdev(xs), min(xs), max(xs))


def analyse(path, window, csv_dir):
    percs, cmds = load(path)
    name = os.path.basename(path).rsplit('.', 1)[0]
    ts = [p.get('t') for p in percs]
    dts = [b - a for a, b in zip(ts, ts[1:]) if a is not None and b is not None]
    res = {'name': name, 'n_perc': len(percs), 'dt_median': st.median(dts) if dts else float('nan'),
           'dt_max': max(dts) if dts else float('nan')}
    k0 = next((i for i, p in enumerate(percs) if p.get('pm') and p['pm'] != 'BeforeKickOff'), None)
    if k0 is None:
        print(f'{name}: no kick-off seen', file=sys.stderr); k0 = 0
    k1 = len(percs)
    if window:
        k1 = next((i for i in range(k0, len(percs)) if percs[i].get('t', 0) - percs[k0].get('t', 0) >= window), len(percs))
    res['k0'], res['k1'] = k0, k1
    res['t0'] = percs[k0].get('t'); res['t1'] = percs[k1 - 1].get('t')
    res['pm0'] = percs[k0].get('pm')
    W = percs[k0:k1]
    # low-pass ACC like the agent (0.9 old + 0.1 new), run over the whole trace
    lp = None; lps = []
    for p in percs:
        a = p.get('acc')
        if a:
            lp = list(a) if lp is None else [0.9 * o + 0.1 * n for o, n in zip(lp, a)]
        lps.append(lp)
    up = [l[2] > 7 for l in lps[k0:k1] if l]
    res['upright_pct'] = 100 * sum(up) / max(1, len(up))
    # falls: upright (lp z > 7) held 0.5 s (25 cycles) -> lp z < 5 (hysteresis, so threshold flicker is not counted)
    falls = 0; run = 0; armed = False
    for l in lps[k0:k1]:
        if not l: continue
        if l[2] > 7:
            run += 1
            if run >= 25: armed = True
        else:
            run = 0
            if armed and l[2] < 5:
                falls += 1; armed = False
    res['falls'] = falls
    # the agent's own fall test (behaviors/checkfall.cc) on its low-passed ACC in agent axes (x_a = -y_srv,
    # y_a = x_srv): fallenUp x_a < -6.5, fallenDown x_a > 7.5, fallenRight y_a < -6.5, fallenLeft y_a > 6.5
    flag = [(-l[1] < -6.5) or (-l[1] > 7.5) or (l[0] < -6.5) or (l[0] > 6.5) for l in lps[k0:k1] if l]
    res['agent_fall_flag_pct'] = 100 * sum(flag) / max(1, len(flag))
    res['agent_fall_flag_events'] = sum(1 for a, b in zip(flag, flag[1:]) if b and not a)
    m = [st.fmean(p['acc'][i] for p in W if 'acc' in p) for i in range(3)]
    res['norm_of_mean_acc'] = math.sqrt(sum(x * x for x in m))
    Wu = [p for p, l in zip(W, lps[k0:k1]) if l and l[2] > 7]
    res['n_upright'] = len(Wu)
    for foot in ('lf', 'rf'):
        res[f'up_frp_{foot}'] = stats([p['frp'][foot][1][2] if foot in p['frp'] else 0.0 for p in Wu])
        res[f'up_frp_{foot}_nocontact_pct'] = 100 * sum(1 for p in Wu if foot not in p['frp']) / max(1, len(Wu))
    res['up_frp_both_off_pct'] = 100 * sum(1 for p in Wu if 'lf' not in p['frp'] and 'rf' not in p['frp']) / max(1, len(Wu))
    res['up_frp_sum'] = stats([sum(p['frp'][f][1][2] for f in ('lf', 'rf') if f in p['frp']) for p in Wu])
    res['up_gyr_std'] = tuple(stats([p['gyr'][i] for p in Wu if 'gyr' in p])[1] for i in range(3))
    for i, ax in enumerate('xyz'):
        res[f'acc_{ax}'] = stats([p['acc'][i] for p in W if 'acc' in p])
        res[f'gyr_{ax}'] = stats([p['gyr'][i] for p in W if 'gyr' in p])
    # ACC while upright (low-passed z > 7): stance-ish
    res['acc_z_upright'] = stats([p['acc'][2] for p, l in zip(W, lps[k0:k1]) if 'acc' in p and l and l[2] > 7])
    res['acc_xy_upright_std'] = (stats([p['acc'][0] for p, l in zip(W, lps[k0:k1]) if 'acc' in p and l and l[2] > 7])[1],
                                 stats([p['acc'][1] for p, l in zip(W, lps[k0:k1]) if 'acc' in p and l and l[2] > 7])[1])
    for foot in ('lf', 'rf'):
        fz = [p['frp'][foot][1][2] if foot in p['frp'] else 0.0 for p in W]
        res[f'frp_{foot}'] = stats(fz)
        res[f'frp_{foot}_nocontact_pct'] = 100 * sum(1 for p in W if foot not in p['frp']) / max(1, len(W))
        res[f'frp_{foot}_p95'] = sorted(fz)[int(0.95 * (len(fz) - 1))] if fz else float('nan')
    both = [sum(p['frp'][f][1][2] for f in ('lf', 'rf') if f in p['frp']) for p in W]
    res['frp_sum'] = stats(both)
    res['frp_both_off_pct'] = 100 * sum(1 for p in W if 'lf' not in p['frp'] and 'rf' not in p['frp']) / max(1, len(W))
    # joint tracking: measured velocity over cycle k-1 -> k vs command sent after perception k-L
    track = {}
    for L in (0, 1, 2, 3):
        errs, gains_num, gains_den, sat = [], 0.0, 0.0, []
        for k in range(max(k0, 1 + L), k1):
            a, b = percs[k - 1], percs[k]
            c = cmds.get(percs[k - 1 - L]['cyc'])  # cmds are keyed by the cyc of the perception they answer
            if not c: continue
            dt = (b.get('t', 0) - a.get('t', 0)) or 0.02
            for j in LEG:
                if j in a['hj'] and j in b['hj'] and eff(j) in c:
                    v = math.radians(b['hj'][j] - a['hj'][j]) / dt
                    u = c[eff(j)]
                    errs.append(v - u); gains_num += v * u; gains_den += u * u
        if errs:
            track[L] = (math.sqrt(st.fmean([e * e for e in errs])), gains_num / gains_den if gains_den else float('nan'), len(errs))
    res['track'] = track
    # same, only cycles where the agent is upright (lp ACC z > 7) and no leg command exceeds 20 rad/s (kick and
    # get-up skills), with the command clipped to +-7.03 rad/s (the Nao's max joint speed in rcssserver3d's rsg)
    trc = {}
    for L in (0, 1, 2):
        errs, gn, gd = [], 0.0, 0.0
        for k in range(max(k0, 1 + L), k1):
            a, b = percs[k - 1], percs[k]
            c = cmds.get(percs[k - 1 - L]['cyc'])
            if not c or not lps[k] or lps[k][2] <= 7 or any(abs(c.get(eff(j), 0)) > 20 for j in LEG): continue
            dt = (b.get('t', 0) - a.get('t', 0)) or 0.02
            for j in LEG:
                if j in a['hj'] and j in b['hj'] and eff(j) in c:
                    v = math.radians(b['hj'][j] - a['hj'][j]) / dt
                    u = max(-7.03, min(7.03, c[eff(j)]))
                    errs.append(v - u); gn += v * u; gd += u * u
        if errs:
            trc[L] = (math.sqrt(st.fmean([e * e for e in errs])), gn / gd if gd else float('nan'), len(errs))
    res['track_clip'] = trc
    # per joint at L=1: gain and RMS
    pj = {}
    for j in LEG:
        num = den = 0.0; e2 = []
        for k in range(max(k0, 2), k1):
            a, b = percs[k - 1], percs[k]; c = cmds.get(percs[k - 2]['cyc'])
            if not c or j not in a['hj'] or j not in b['hj'] or eff(j) not in c: continue
            dt = (b.get('t', 0) - a.get('t', 0)) or 0.02
            v = math.radians(b['hj'][j] - a['hj'][j]) / dt; u = c[eff(j)]
            num += v * u; den += u * u; e2.append((v - u) ** 2)
        if e2: pj[j] = (num / den if den else float('nan'), math.sqrt(st.fmean(e2)))
    res['perjoint'] = pj
    # command magnitude
    cm = [abs(cmds[p['cyc']][eff(j)]) for p in W if p['cyc'] in cmds for j in LEG if eff(j) in cmds[p['cyc']]]
    res['cmd_abs'] = stats(cm)
    if csv_dir:
        os.makedirs(csv_dir, exist_ok=True)
        allj = sorted({j for p in percs for j in p['hj']})
        with open(os.path.join(csv_dir, name + '.csv'), 'w') as f:
            hdr = ['k', 'cyc', 't', 'pm', 'gyr_x', 'gyr_y', 'gyr_z', 'acc_x', 'acc_y', 'acc_z', 'acc_lp_z',
                   'lf_fz', 'rf_fz', 'lf_cx', 'lf_cy', 'rf_cx', 'rf_cy'] + [f'hj_{j}' for j in allj] + [f'cmd_{eff(j)}' for j in allj]
            f.write(','.join(hdr) + '\n')
            for k, p in enumerate(percs):
                c = cmds.get(p['cyc'], {})
                row = [k, p['cyc'], p.get('t', ''), p.get('pm', '')] + (p.get('gyr') or ['', '', '']) + (p.get('acc') or ['', '', '']) + \
                      [round(lps[k][2], 4) if lps[k] else ''] + \
                      [p['frp'][ft][1][2] if ft in p['frp'] else 0 for ft in ('lf', 'rf')] + \
                      [p['frp'][ft][0][i] if ft in p['frp'] else '' for ft in ('lf', 'rf') for i in (0, 1)] + \
                      [p['hj'].get(j, '') for j in allj] + [c.get(eff(j), '') for j in allj]
                f.write(','.join(str(x) for x in row) + '\n')
    return res


def fmt(v):
    if isinstance(v, tuple):
        return ' '.join(f'{x:8.3f}' for x in v)
    if isinstance(v, float):
        return f'{v:8.3f}'
    return str(v)


def main():
    import argparse
    ap = argparse.ArgumentParser()
    ap.add_argument('traces', nargs='+'); ap.add_argument('--csv-dir'); ap.add_argument('--window', type=float)
    ap.add_argument('--timeline', action='store_true', help='per-second summary of each trace')
    a = ap.parse_args()
    if a.timeline:
        for path in a.traces:
            percs, cmds = load(path)
            print(f'== {path}: per 1 s of perceptions: t pm | ACC z mean (min..max) | GYR |x|,|y| mean | '
                  f'FRP lf, rf mean N | cycles with no foot contact /50')
            for i in range(0, len(percs), 50):
                seg = [p for p in percs[i:i + 50] if 'acc' in p]
                if not seg: continue
                az = [p['acc'][2] for p in seg]
                g = lambda k: st.fmean(abs(p['gyr'][k]) for p in seg if 'gyr' in p)
                fz = lambda f: st.fmean(p['frp'][f][1][2] if f in p['frp'] else 0 for p in seg)
                off = sum(1 for p in seg if not p['frp'])
                print(f"{seg[0].get('t', 0):7.2f} {seg[0].get('pm', '?'):14s} | {st.fmean(az):6.2f} ({min(az):6.2f}..{max(az):6.2f}) "
                      f"| {g(0):6.1f} {g(1):6.1f} | {fz('lf'):6.1f} {fz('rf'):6.1f} | {off:2d}")
    R = [analyse(p, a.window, a.csv_dir) for p in a.traces]
    keys = ['name', 'n_perc', 'dt_median', 'dt_max', 'k0', 'k1', 't0', 't1', 'pm0', 'upright_pct', 'falls', 'agent_fall_flag_pct', 'agent_fall_flag_events', 'norm_of_mean_acc',
            'acc_x', 'acc_y', 'acc_z', 'acc_z_upright', 'acc_xy_upright_std', 'gyr_x', 'gyr_y', 'gyr_z',
            'frp_lf', 'frp_rf', 'frp_lf_p95', 'frp_rf_p95', 'frp_lf_nocontact_pct', 'frp_rf_nocontact_pct',
            'frp_both_off_pct', 'frp_sum', 'n_upright', 'up_frp_lf', 'up_frp_rf', 'up_frp_lf_nocontact_pct',
            'up_frp_rf_nocontact_pct', 'up_frp_both_off_pct', 'up_frp_sum', 'up_gyr_std', 'cmd_abs']
    print('stats tuples = mean std min max (ACC m/s^2, GYR deg/s, FRP N, cmd rad/s)')
    for k in keys:
        print(f'{k:22s} | ' + ' | '.join(f'{fmt(r[k]):>36s}' for r in R))
    print('joint tracking, 12 leg joints: measured dHJ/dt over cycle k-1->k vs command sent after perception k-1-L')
    print('  L = extra cycles of latency; columns: RMS error rad/s, gain (LS slope measured/commanded), samples')
    for L in (0, 1, 2, 3):
        print(f'  L={L}                 | ' + ' | '.join(
            f'{fmt(r["track"][L][:2]) if L in r["track"] else "-":>27s} n={r["track"].get(L, (0, 0, 0))[2]:6d}' for r in R))

    print('  same, upright cycles only, no leg command > 20 rad/s, command clipped to +-7.03 rad/s:')
    for L in (0, 1, 2):
        print(f'  L={L}                 | ' + ' | '.join(
            f'{fmt(r["track_clip"][L][:2]) if L in r["track_clip"] else "-":>27s} n={r["track_clip"].get(L, (0, 0, 0))[2]:6d}' for r in R))
    print('per leg joint at L=1 (gain, RMS rad/s):')
    for j in LEG:
        print(f'  {j:20s} | ' + ' | '.join(f'{fmt(r["perjoint"].get(j, (float("nan"),) * 2)):>36s}' for r in R))


if __name__ == '__main__':
    main()
