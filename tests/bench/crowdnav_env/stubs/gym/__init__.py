# Minimal stand-in for gym: CrowdNav's env only subclasses gym.Env and registers an id.
class Env:
    pass
