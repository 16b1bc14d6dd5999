# "Tunnels when a step is longer than the window": ignores where the steps fall.
def detected(gap, speed, dt, sigma):
    return speed * dt < 2 * sigma
