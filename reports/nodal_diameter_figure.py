"""The nodal-diameter map figure (the paper's Fig. 3 in 3D) from the rows of
nodal_diameters.csv (part, index, frequency_hz, nodal_diameter), shared by
make_rubbing_report.py and make_system_sweep_report.py."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def draw_nodal_diameter_map(nd_rows, path):
    """Each part's modes as (nodal diameter, frequency) points; written to `path`."""
    fig, ax = plt.subplots(figsize=(6, 4))
    for part, marker, color in (("bladed-disk", "o", "C0"), ("casing", "s", "C3")):
        pts = [(int(r["nodal_diameter"]), float(r["frequency_hz"])) for r in nd_rows
               if r["part"] == part]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, color=color, ms=5,
                mfc="none", label=part)
    ax.set_xlabel("nodal diameters (casing: lobes)")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title("nodal-diameter map")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
