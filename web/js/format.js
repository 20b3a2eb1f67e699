// Numbers, shares with their standard errors, times and names as the page writes them.

const intFormat = new Intl.NumberFormat('en-US', { maximumFractionDigits: 0 });
export function fmtInt(v) { return Number.isFinite(v) ? intFormat.format(v) : '—'; }
export function fmtNumber(v, digits = 3) {
  return Number.isFinite(v) ? v.toLocaleString('en-US', { maximumFractionDigits: digits }) : '—';
}
// Decimals that show the standard error to two significant figures (in percentage points).
export function decimalsFor(stderrPct) {
  if (!(stderrPct > 0)) return 2;
  return Math.min(4, Math.max(1, 1 - Math.floor(Math.log10(stderrPct))));
}
export function fmtPct(share, stderr) {
  if (!Number.isFinite(share)) return '—';
  const d = decimalsFor(stderr * 100);
  return `${(share * 100).toFixed(d)} %`;
}
export function fmtPctErr(share, stderr) {
  if (!Number.isFinite(share)) return '—';
  const d = decimalsFor(stderr * 100);
  return `${(share * 100).toFixed(d)} % ± ${(stderr * 100).toFixed(d)}`;
}
export function fmtTime(iso) {
  if (!iso) return '';
  const t = new Date(iso);
  if (Number.isNaN(t.getTime())) return iso;
  const sameDay = t.toDateString() === new Date().toDateString();
  return sameDay ? t.toLocaleTimeString('en-GB') : t.toLocaleString('en-GB', { dateStyle: 'medium', timeStyle: 'short' });
}
export function fmtDuration(seconds) {
  if (!Number.isFinite(seconds)) return '—';
  return seconds < 60 ? `${seconds.toFixed(seconds < 10 ? 2 : 1)} s` : `${Math.floor(seconds / 60)} min ${Math.round(seconds % 60)} s`;
}
export function humanize(name) { return String(name).replace(/_/g, ' '); }
export function shortId(id) { return String(id).slice(0, 8); }
