"""One line per backend that says what it is, on the first screen (issue 48, item 1): its
algorithm (BackendInfo's description), the precision it computed in, the device it ran on and
its preset (from its cases' provenance, summary.json `backends.B.ran_on`), and what it claims
(BackendInfo: exact, the stepping rule, what it conserves): a claim the checks below test, not a
finding. Nothing is judged here.
"""
import digest


def _precision(info):
    """'float' or 'float (offers double)': the precision it ran in, then the declared one."""
    ran = (info.get("ran_on") or {}).get("precision")
    declared = info.get("precision", "")
    if ran and ran != declared:
        return f"{ran} (offers {declared.replace('|', ' or ')})"
    return declared.replace("|", " or ") or "not declared"


def _device(ran_on):
    """'on the CPU: OpenCL device "pthread-…" of platform "Portable Computing Language"',
    or 'on the CPU (N threads per case)' for a backend without a device of its own."""
    device = ran_on.get("device")
    if not device:
        threads = ran_on.get("threads")
        return "on the CPU" + (f", {threads} threads per case" if threads else ", serial")
    kind = ran_on.get("device_type") or "device"
    where = f"on the {kind}" if kind in ("CPU", "GPU") else f"on a {kind}"
    return f"{where}: device “{device}” of platform “{ran_on.get('platform', 'not recorded')}”"


def _claims(info):
    claims = []
    if info.get("exact"):
        claims.append("claims exact dynamics (event-driven, no time step)")
    if info.get("rule"):
        claims.append("implements the stepping rule " + info["rule"].replace("|", " or ") +
                      " (the scene's order)")
    if info.get("conserves"):
        claims.append("conserves " + " and ".join(info["conserves"]) + " up to rounding")
    return claims or ["claims no conservation law"]


def _short(info, ran_on):
    """The digest's second line under the name: 'float · CPU, Portable Computing Language ·
    stepping rule · preset: shipped'."""
    device = ran_on.get("device_type") or "CPU"
    if ran_on.get("platform"):
        device += ", " + ran_on["platform"]
    elif ran_on.get("threads"):
        device += f", {ran_on['threads']} threads"
    claim = "exact (a claim)" if info.get("exact") else "stepping rule" if info.get("rule") else "its own method"
    precision = ran_on.get("precision") or info.get("precision", "").replace("|", " or ")
    parts = [precision, device, claim]
    if ran_on.get("preset"):
        parts.append("preset: " + ran_on["preset"])
    return " · ".join(parts)


def backend_line(name, info, reference):
    """{'backend', 'anchor', 'text', 'short'} for one backend of summary.json's `backends`."""
    ran_on = info.get("ran_on") or {}
    parts = [info.get("description") or name, _precision(info), _device(ran_on)]
    parts += _claims(info)
    preset = ran_on.get("preset") or ran_on.get("variant_settings")
    if preset:
        parts.append(f"preset: {preset}")
    if name == reference:
        parts.append("every error below is measured against it")
    return {"backend": name, "anchor": digest.anchor("backend", name), "text": "; ".join(parts),
            "short": _short(info, ran_on)}


def backend_lines(summary):
    """One line per backend, in the digest's order."""
    backends = summary.get("backends", {})
    return [backend_line(b, backends[b], summary["reference"]) for b in digest.backends_in_order(summary)
            if b in backends]
