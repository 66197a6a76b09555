# Minimal stand-in: CrowdNav's env imports matplotlib at the top only for render().
