"""What the benches' error-against-time plots share: a log time axis in plain seconds."""


def error_against_time(ax, ticks, title, error_label):
    """Log time axis with `ticks` written as plain numbers, error from 0, a light grid."""
    import matplotlib.ticker

    ax.set_xscale("log")
    ax.xaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.set_xticks(ticks)
    ax.set_ylim(0, None)
    ax.set_xlabel("solve time (s), 2-core VM")
    ax.set_ylabel(error_label)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
