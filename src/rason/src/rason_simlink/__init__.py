"""The sim link's pieces that need no ROS: record framing, the relayed topics, presence
bookkeeping and rate-limited reporting (the rospy node is scripts/sim_link)."""
