"""The stacked plots of the ram's and the lever's motion and of the forces, and the plot parts they share."""
